#include "dfvn/noise/steerable_noise.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/LU>
#include <fmt/format.h>

#include "dfvn/core/direction.hpp"
#include "dfvn/noise/quintic_fade.hpp"

namespace dfvn {

void check_steer_spec(const SteerSpec& spec, int dimension) {
  if (dimension < 2 || dimension > kMaxSteerableDimension)
    throw std::invalid_argument(fmt::format("steerable noise is defined in 2D to 4D (2^N corners per function), not in {}D", dimension));
  if (spec.circular && !spec.direction.empty())
    throw std::invalid_argument("steerable noise takes one direction field: --steer-dir or --steer-field circular, not both");
  if (!spec.circular && spec.direction.empty())
    throw std::invalid_argument("steerable noise needs a direction: --steer-dir U (N components) or --steer-field circular");
  if (!spec.circular) {
    if (static_cast<int>(spec.direction.size()) != dimension)
      throw std::invalid_argument(fmt::format("--steer-dir has {} components; the dimension is {}", spec.direction.size(), dimension));
    for (double c : spec.direction)
      if (!std::isfinite(c)) throw std::invalid_argument("--steer-dir has a non-finite component");
    if (!is_direction(spec.direction)) throw std::invalid_argument("--steer-dir must be a non-zero direction");
  }
  const double isotropic = (4.0 - (dimension - 1) * kSteerEpsilon) / dimension;
  if (!(spec.k > 0.0 && spec.k <= 1.0 && spec.k < isotropic))
    throw std::invalid_argument(fmt::format(
        "--steer-k must be in (0, 1] and below (4 - (N-1) 1e-4) / N = {:.6g} in {}D (the eigenvalue along u the smallest), got {:g}",
        isotropic, dimension, spec.k));
}

template <int N>
Eigen::Matrix<double, N, N> steer_metric(const Vec<N>& unit_direction, double k) {
  const double a = (4.0 - k) / (N - 1) - kSteerEpsilon;
  Eigen::Matrix<double, N, N> g = (k - a) * (unit_direction * unit_direction.transpose());
  g.diagonal().array() += a;
  return g;
}

namespace {

// phi(t) = 1 - s(t) on [0, 1], 0 beyond (t >= 0), and its derivative.
inline double falloff(double t) { return t < 1.0 ? 1.0 - quintic_fade(t) : 0.0; }
inline double falloff_slope(double t) { return t < 1.0 ? -quintic_fade_slope(t) : 0.0; }

// Roberts' R_N sequence (as field/dfvn_field.cpp): alpha_j = phi^-(j+1), phi the root of x^(N+1) = x + 1.
template <int N>
Vec<N> kronecker_step() {
  double phi = 2.0;
  for (int k = 0; k < 64; ++k) phi -= (std::pow(phi, N + 1) - phi - 1.0) / ((N + 1) * std::pow(phi, N) - 1.0);
  Vec<N> alpha;
  for (int j = 0; j < N; ++j) alpha[j] = std::fmod(std::pow(phi, -(j + 1)), 1.0);
  return alpha;
}

}  // namespace

template <int N>
SteerableNoise<N>::SteerableNoise(std::uint64_t seed, double phase, const SteerSpec& spec)
    : lattice_((check_steer_spec(spec, N), seed), phase), spec_(spec) {
  across_ = (4.0 - spec.k) / (N - 1) - kSteerEpsilon;
  isotropic_ = (4.0 - (N - 1) * kSteerEpsilon) / N;
  if (!spec.circular) {
    for (int j = 0; j < N; ++j) u_[j] = spec.direction[j];
    u_ = unit_direction<N>(u_);
    constant_metric_ = steer_metric<N>(u_, spec.k);
  }
  // The moments over 2^15 Kronecker points of [-32, 32)^N, summed in point order (deterministic).
  constexpr int kPoints = 1 << 15;
  constexpr double kSide = 64.0;
  const Vec<N> alpha = kronecker_step<N>();
  double value2 = 0.0, gradient2 = 0.0, cross2 = 0.0;
  for (int p = 0; p < kPoints; ++p) {
    Vec<N> y;
    for (int j = 0; j < N; ++j) y[j] = kSide * (std::fmod(0.5 + p * alpha[j], 1.0) - 0.5);
    const NoiseSample<N, N - 1> s = evaluate(y);
    Eigen::Matrix<double, N, N - 1> jac;
    for (int i = 0; i < N - 1; ++i) {
      value2 += s.value[i] * s.value[i];
      gradient2 += s.gradient[i].squaredNorm();
      jac.col(i) = s.gradient[i];
    }
    // |cross(g_1, ..., g_{N-1})|^2 is the Gram determinant of the N-1 gradients.
    const Eigen::Matrix<double, N - 1, N - 1> gram = jac.transpose() * jac;
    cross2 += gram.determinant();
  }
  if (!(value2 > 0.0 && gradient2 > 0.0 && cross2 > 0.0)) throw std::logic_error("steerable noise without variation");
  wavenumber_ = std::sqrt(gradient2 / value2);
  amplitude_ = std::pow(cross2 / kPoints, -0.5 / (N - 1));
}

template <int N>
typename SteerableNoise<N>::Matrix SteerableNoise<N>::metric(const Vec<N>& y, std::array<Matrix, N>* derivatives) const {
  if (!spec_.circular) {
    if (derivatives)
      for (auto& d : *derivatives) d.setZero();
    return constant_metric_;
  }
  // G = c I + (k - a) u u^T / q with u = (-y_1, y_0, 0, ...), q = r^2 + d^2, c = g0 + (a - g0) r^2 / q.
  Vec<N> u = Vec<N>::Zero();
  u[0] = -y[1];
  u[1] = y[0];
  const double r2 = y[0] * y[0] + y[1] * y[1];
  const double core2 = kSteerCircularCore * kSteerCircularCore;
  const double q = r2 + core2;
  const double slope = spec_.k - across_;
  const double c = isotropic_ + (across_ - isotropic_) * r2 / q;
  Matrix g = (slope / q) * (u * u.transpose());
  g.diagonal().array() += c;
  if (derivatives) {
    for (auto& d : *derivatives) d.setZero();
    for (int j = 0; j < 2; ++j) {
      const double dr2 = 2.0 * y[j];
      Vec<N> du = Vec<N>::Zero();  // d u / d y_j
      if (j == 0) du[1] = 1.0;
      else du[0] = -1.0;
      Matrix& d = (*derivatives)[j];
      d = (slope / q) * (du * u.transpose() + u * du.transpose()) - (slope * dr2 / (q * q)) * (u * u.transpose());
      d.diagonal().array() += (across_ - isotropic_) * core2 * dr2 / (q * q);
    }
  }
  return g;
}

template <int N>
double SteerableNoise<N>::weight_sum(int function, const Vec<N>& y) const {
  const Matrix g = metric(y);
  const auto& rotation = lattice_.rotation(function);
  const Vec<N> z = rotation * y + lattice_.offset(function);
  Vec<N> f;
  for (int d = 0; d < N; ++d) f[d] = z[d] - std::floor(z[d]);
  double sum = 0.0;
  for (int corner = 0; corner < kCorners; ++corner) {
    Vec<N> v;
    double perlin = 1.0;
    for (int d = 0; d < N; ++d) {
      v[d] = static_cast<double>((corner >> d) & 1) - f[d];
      perlin *= falloff(std::abs(v[d]));
    }
    const Vec<N> vw = rotation.transpose() * v;
    sum += perlin * falloff(vw.dot(g * vw));
  }
  return sum;
}

template <int N>
NoiseSample<N, N - 1> SteerableNoise<N>::evaluate(const Vec<N>& y) const {
  std::array<Matrix, N> dg;
  const Matrix g = metric(y, spec_.circular ? &dg : nullptr);
  const bool phased = lattice_.phase() != 0.0;
  NoiseSample<N, N - 1> out;
  for (int i = 0; i < N - 1; ++i) {
    const auto& rotation = lattice_.rotation(i);
    const Vec<N> z = rotation * y + lattice_.offset(i);
    std::array<std::int64_t, N> cell;
    Vec<N> f;
    for (int d = 0; d < N; ++d) {
      cell[d] = static_cast<std::int64_t>(std::floor(z[d]));
      f[d] = z[d] - static_cast<double>(cell[d]);
    }
    double value = 0.0;
    Vec<N> gradient = Vec<N>::Zero();  // with respect to y (world)
    for (int corner = 0; corner < kCorners; ++corner) {
      std::array<std::int64_t, N> point;
      Vec<N> v;  // lattice frame: from the sample to the corner, in (-1, 1]^N
      std::array<double, N> w, dw;  // phi(|v_d|) and d/dv_d phi(|v_d|)
      double perlin = 1.0;
      for (int d = 0; d < N; ++d) {
        const int bit = (corner >> d) & 1;
        point[d] = cell[d] + bit;
        v[d] = static_cast<double>(bit) - f[d];
        const double t = std::abs(v[d]);
        w[d] = falloff(t);
        dw[d] = v[d] < 0.0 ? -falloff_slope(t) : falloff_slope(t);
        perlin *= w[d];
      }
      if (perlin == 0.0) continue;  // every factor of the term and of its gradient vanishes with P (C2 at |v_d| = 1)
      const Vec<N> vw = rotation.transpose() * v;
      const Matrix& r = rotation;
      const Vec<N> gw = r.transpose() * (phased ? lattice_.rotated_lattice_gradient(i, point) : lattice_.lattice_gradient(i, point));
      const Vec<N> gv = g * vw;
      const double q = vw.dot(gv);
      const double aniso = falloff(q);
      if (aniso == 0.0) continue;  // q >= 1: phi, phi' (and phi'') are 0
      const double aniso_slope = falloff_slope(q);
      const double dot = gw.dot(gv);
      value += dot * perlin * aniso;
      // d/dv of P in the lattice frame (product rule), turned into world coordinates below.
      Vec<N> dperlin;
      for (int d = 0; d < N; ++d) {
        double others = 1.0;
        for (int e = 0; e < N; ++e)
          if (e != d) others *= w[e];
        dperlin[d] = dw[d] * others;
      }
      // v_w = R^T (corner - o) - y, so d v_w / d y = -I and d v / d y = -R:
      gradient -= (perlin * aniso) * (g * gw) + (dot * aniso) * (r.transpose() * dperlin) +
                  (2.0 * dot * perlin * aniso_slope) * gv;
      if (spec_.circular)
        for (int j = 0; j < N; ++j)
          gradient[j] += perlin * (aniso * gw.dot(dg[j] * vw) + dot * aniso_slope * vw.dot(dg[j] * vw));
    }
    out.value[i] = value;
    out.gradient[i] = gradient;
  }
  return out;
}

template <int N>
std::shared_ptr<const NoiseFunctions<N>> make_steerable_noise(std::uint64_t seed, double phase, const SteerSpec& spec) {
  check_noise_phase(phase);
  check_steer_spec(spec, N);
  if constexpr (N <= kMaxSteerableDimension) return std::make_shared<const SteerableNoise<N>>(seed, phase, spec);
  else throw std::logic_error("unreachable: check_steer_spec refuses N > 4");
}

#define DFVN_INSTANTIATE(N) \
  template std::shared_ptr<const NoiseFunctions<N>> make_steerable_noise<N>(std::uint64_t, double, const SteerSpec&);
DFVN_INSTANTIATE(2)
DFVN_INSTANTIATE(3)
DFVN_INSTANTIATE(4)
DFVN_INSTANTIATE(5)
DFVN_INSTANTIATE(6)
DFVN_INSTANTIATE(7)
DFVN_INSTANTIATE(8)
#undef DFVN_INSTANTIATE

template Eigen::Matrix<double, 2, 2> steer_metric<2>(const Vec<2>&, double);
template Eigen::Matrix<double, 3, 3> steer_metric<3>(const Vec<3>&, double);
template Eigen::Matrix<double, 4, 4> steer_metric<4>(const Vec<4>&, double);
template class SteerableNoise<2>;
template class SteerableNoise<3>;
template class SteerableNoise<4>;

}  // namespace dfvn
