#include "dfvn/quadrature/genz.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

#include "dfvn/core/hash.hpp"

namespace dfvn {

std::string_view to_string(GenzFamily family) {
  switch (family) {
    case GenzFamily::oscillatory: return "oscillatory";
    case GenzFamily::product_peak: return "product_peak";
    case GenzFamily::corner_peak: return "corner_peak";
    case GenzFamily::gaussian: return "gaussian";
    case GenzFamily::continuous: return "continuous";
    case GenzFamily::discontinuous: return "discontinuous";
  }
  return "?";
}

double genz_difficulty(GenzFamily family) {
  switch (family) {
    case GenzFamily::oscillatory: return 9.0;
    case GenzFamily::product_peak: return 7.25;
    case GenzFamily::corner_peak: return 1.85;
    case GenzFamily::gaussian: return 7.03;
    case GenzFamily::continuous: return 20.4;
    case GenzFamily::discontinuous: return 4.3;
  }
  return 1.0;
}

double GenzIntegrand::operator()(const double* x) const {
  const int n = dimension();
  switch (family) {
    case GenzFamily::oscillatory: {
      double phase = 2.0 * std::numbers::pi * u[0];
      for (int i = 0; i < n; ++i) phase += a[i] * x[i];
      return std::cos(phase);
    }
    case GenzFamily::product_peak: {
      double value = 1.0;
      for (int i = 0; i < n; ++i) value /= 1.0 / (a[i] * a[i]) + (x[i] - u[i]) * (x[i] - u[i]);
      return value;
    }
    case GenzFamily::corner_peak: {
      double s = 1.0;
      for (int i = 0; i < n; ++i) s += a[i] * x[i];
      return std::pow(s, -(n + 1));
    }
    case GenzFamily::gaussian: {
      double s = 0.0;
      for (int i = 0; i < n; ++i) s += a[i] * a[i] * (x[i] - u[i]) * (x[i] - u[i]);
      return std::exp(-s);
    }
    case GenzFamily::continuous: {
      double s = 0.0;
      for (int i = 0; i < n; ++i) s += a[i] * std::abs(x[i] - u[i]);
      return std::exp(-s);
    }
    case GenzFamily::discontinuous: {
      if (x[0] > u[0] || (n > 1 && x[1] > u[1])) return 0.0;
      double s = 0.0;
      for (int i = 0; i < n; ++i) s += a[i] * x[i];
      return std::exp(s);
    }
  }
  return 0.0;
}

double GenzIntegrand::exact_integral() const {
  const int n = dimension();
  double value = 1.0;
  switch (family) {
    case GenzFamily::oscillatory: {
      // Re[e^{2 pi i u_1} prod_i int_0^1 e^{i a_i x} dx] with int_0^1 e^{i a x} dx = (e^{i a} - 1) / (i a).
      std::complex<double> z = std::polar(1.0, 2.0 * std::numbers::pi * u[0]);
      for (int i = 0; i < n; ++i) z *= (std::polar(1.0, a[i]) - 1.0) / std::complex<double>(0.0, a[i]);
      return z.real();
    }
    case GenzFamily::product_peak:
      // int_0^1 dx / (a^-2 + (x - u)^2) = a [atan(a (1 - u)) + atan(a u)].
      for (int i = 0; i < n; ++i) value *= a[i] * (std::atan(a[i] * (1.0 - u[i])) + std::atan(a[i] * u[i]));
      return value;
    case GenzFamily::corner_peak: {
      // Integrating (c + a_k x_k)^-m over x_k in [0,1] gives [c^-(m-1) - (c + a_k)^-(m-1)] / ((m-1) a_k);
      // N times from m = N+1: 1 / (N! prod a_i) * sum_{v in {0,1}^N} (-1)^|v| / (1 + a.v).
      double sum = 0.0;
      for (std::uint32_t v = 0; v < (1u << n); ++v) {
        double s = 1.0;
        int bits = 0;
        for (int i = 0; i < n; ++i)
          if (v & (1u << i)) {
            s += a[i];
            ++bits;
          }
        sum += (bits % 2 ? -1.0 : 1.0) / s;
      }
      for (int i = 0; i < n; ++i) value *= (i + 1) * a[i];
      return sum / value;
    }
    case GenzFamily::gaussian:
      // int_0^1 e^{-a^2 (x - u)^2} dx = sqrt(pi) / (2a) [erf(a (1 - u)) + erf(a u)].
      for (int i = 0; i < n; ++i)
        value *= std::sqrt(std::numbers::pi) / (2.0 * a[i]) * (std::erf(a[i] * (1.0 - u[i])) + std::erf(a[i] * u[i]));
      return value;
    case GenzFamily::continuous:
      // int_0^1 e^{-a |x - u|} dx = [2 - e^{-a u} - e^{-a (1 - u)}] / a.
      for (int i = 0; i < n; ++i) value *= (2.0 - std::exp(-a[i] * u[i]) - std::exp(-a[i] * (1.0 - u[i]))) / a[i];
      return value;
    case GenzFamily::discontinuous:
      // int_0^c e^{a x} dx = (e^{a c} - 1) / a, with c = u_i on the first two axes and 1 on the others.
      for (int i = 0; i < n; ++i) value *= std::expm1(a[i] * (i < 2 ? u[i] : 1.0)) / a[i];
      return value;
  }
  return 0.0;
}

GenzIntegrand random_genz_integrand(GenzFamily family, int dimension, std::uint64_t seed) {
  if (dimension < 1 || dimension > 20) throw std::invalid_argument("Genz integrands are defined here for 1..20 dimensions");
  GenzIntegrand f;
  f.family = family;
  f.a.resize(static_cast<std::size_t>(dimension));
  f.u.resize(static_cast<std::size_t>(dimension));
  const auto family_index = static_cast<std::uint64_t>(family);
  double raw_sum = 0.0;
  for (int i = 0; i < dimension; ++i) {
    const auto axis = static_cast<std::uint64_t>(i);
    // Widths in [0.05, 1.05) before scaling, so that no axis is left without any variation.
    f.a[i] = 0.05 + random_unit(seed, Stream::genz, family_index, 2 * axis);
    f.u[i] = random_unit(seed, Stream::genz, family_index, 2 * axis + 1);
    raw_sum += f.a[i];
  }
  for (double& width : f.a) width *= genz_difficulty(family) / raw_sum;
  return f;
}

}  // namespace dfvn
