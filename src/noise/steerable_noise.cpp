#include "dfvn/noise/steerable_noise.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <Eigen/LU>
#include <fmt/format.h>

#include "dfvn/core/direction.hpp"
#include "dfvn/noise/quintic_fade.hpp"

namespace dfvn {

void check_steer_spec(const SteerSpec& spec, int dimension) {
  if (dimension < 2 || dimension > kMaxSteerableDimension)
    throw std::invalid_argument(fmt::format("steerable noise is defined in 2D to 4D (2^N corners per function), not in {}D", dimension));
  const int fields = (spec.circular ? 1 : 0) + (spec.direction.empty() ? 0 : 1) + (spec.image ? 1 : 0);
  if (fields > 1)
    throw std::invalid_argument(
        "steerable noise takes one direction field, not both (nor three): --steer-dir, --steer-field circular or --steer-image");
  if (fields == 0)
    throw std::invalid_argument(
        "steerable noise needs a direction: --steer-dir U (N components), --steer-field circular or --steer-image FILE");
  if (spec.image && dimension != 2)
    throw std::invalid_argument(fmt::format("--steer-image steers 2D noise (an image is a 2D direction field), not {}D", dimension));
  if (spec.quality < 0 || spec.quality > dimension)
    throw std::invalid_argument(fmt::format("--steer-quality must be in 0..N = 0..{}, got {}", dimension, spec.quality));
  if (!spec.direction.empty()) {
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

// The uniform cubic B-spline's four weights at t in [0, 1) and their derivatives in t.
void bspline_weights(double t, double w[4], double dw[4]) {
  const double t2 = t * t, t3 = t2 * t, u = 1.0 - t;
  w[0] = u * u * u / 6.0;
  w[1] = (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0;
  w[2] = (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0;
  w[3] = t3 / 6.0;
  dw[0] = -0.5 * u * u;
  dw[1] = 1.5 * t2 - 2.0 * t;
  dw[2] = -1.5 * t2 + t + 0.5;
  dw[3] = 0.5 * t2;
}

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

std::array<double, 3> direction_tensor(const DirectionGrid& grid, const Vec<2>& x,
                                       std::array<std::array<double, 3>, 2>* gradient) {
  // Continuous pixel coordinates: column u = x_1 (columns - 1), row v = x_2 (rows - 1).
  const double su = grid.columns - 1, sv = grid.rows - 1;
  const double u = x[0] * su, v = x[1] * sv;
  const double fu = std::floor(u), fv = std::floor(v);
  double wu[4], dwu[4], wv[4], dwv[4];
  bspline_weights(u - fu, wu, dwu);
  bspline_weights(v - fv, wv, dwv);
  std::array<double, 3> h{0.0, 0.0, 0.0};
  std::array<std::array<double, 3>, 2> g{};
  for (int a = 0; a < 4; ++a) {
    const double row_index = std::clamp(fv - 1.0 + a, 0.0, sv);  // clamped: the border continues
    for (int b = 0; b < 4; ++b) {
      const double column_index = std::clamp(fu - 1.0 + b, 0.0, su);
      const auto& t = grid.tensors[static_cast<std::size_t>(row_index) * grid.columns + static_cast<std::size_t>(column_index)];
      for (int c = 0; c < 3; ++c) {
        h[c] += wv[a] * wu[b] * t[c];
        g[0][c] += wv[a] * dwu[b] * su * t[c];
        g[1][c] += dwv[a] * sv * wu[b] * t[c];
      }
    }
  }
  if (gradient) *gradient = g;
  return h;
}

template <int N>
SteerableNoise<N>::SteerableNoise(std::uint64_t seed, double phase, const SteerSpec& spec)
    : lattice_((check_steer_spec(spec, N), seed), phase), spec_(spec) {
  side_ = 2 * spec.quality + 2;
  corners_ = 1;
  for (int d = 0; d < N; ++d) corners_ *= side_;
  weight_scale_ = 1.0 / (spec.quality + 1);  // the document's 2 / (|start| + |end| + 1) = 2 / (2Q + 2)
  steer_k_ = spec.k / (spec.quality + 1);
  across_ = (4.0 - steer_k_) / (N - 1) - kSteerEpsilon;
  isotropic_ = (4.0 - (N - 1) * kSteerEpsilon) / N;
  if (!spec.direction.empty()) {
    for (int j = 0; j < N; ++j) u_[j] = spec.direction[j];
    u_ = unit_direction<N>(u_);
    constant_metric_ = steer_metric<N>(u_, steer_k_);
  }
  if (spec.image) {
    if (!(spec.image_frequency > 0.0))
      throw std::invalid_argument("--steer-image: the field's frequency maps the image onto the unit square (image_frequency unset)");
    // k_eff and the amplitude of the same noise steered by (1, 0), which place the image (module comment).
    SteerSpec constant = spec;
    constant.image = nullptr;
    constant.direction.assign(N, 0.0);
    constant.direction[0] = 1.0;
    const SteerableNoise twin(seed, phase, constant);
    wavenumber_ = twin.wavenumber_;
    amplitude_ = twin.amplitude_;
    image_scale_ = 2.0 * std::numbers::pi * spec.image_frequency / wavenumber_;
    return;
  }
  measure();
}

template <int N>
void SteerableNoise<N>::measure() {
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
  if constexpr (N == 2) {
    if (spec_.image) {  // G = a I + (k - a) H(y / image_scale)
      std::array<std::array<double, 3>, 2> dh;
      const std::array<double, 3> h = direction_tensor(*spec_.image, y / image_scale_, &dh);
      const double slope = steer_k_ - across_;
      Matrix g;
      g << across_ + slope * h[0], slope * h[1], slope * h[1], across_ + slope * h[2];
      if (derivatives)
        for (int j = 0; j < 2; ++j) {
          const double f = slope / image_scale_;  // d/dy = (1 / image_scale) d/dx
          (*derivatives)[j] << f * dh[j][0], f * dh[j][1], f * dh[j][1], f * dh[j][2];
        }
      return g;
    }
  }
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
  const double slope = steer_k_ - across_;
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
  for (int corner = 0; corner < corners_; ++corner) {
    Vec<N> v;
    double perlin = 1.0;
    for (int d = 0, rest = corner; d < N; ++d, rest /= side_) {
      v[d] = static_cast<double>(rest % side_ - spec_.quality) - f[d];
      perlin *= falloff(weight_scale_ * std::abs(v[d]));
    }
    const Vec<N> vw = rotation.transpose() * v;
    sum += perlin * falloff(vw.dot(g * vw));
  }
  return sum;
}

template <int N>
NoiseSample<N, N - 1> SteerableNoise<N>::evaluate(const Vec<N>& y) const {
  std::array<Matrix, N> dg;
  const Matrix g = metric(y, spec_.circular || spec_.image ? &dg : nullptr);
  const bool phased = lattice_.phase() != 0.0;
  const bool varying = spec_.circular || spec_.image != nullptr;
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
    for (int corner = 0; corner < corners_; ++corner) {
      std::array<std::int64_t, N> point;
      Vec<N> v;  // lattice frame: from the sample to the corner, in (-Q-1, Q+1]^N
      std::array<double, N> w, dw;  // phi(|v_d| / (Q+1)) and its derivative in v_d
      double perlin = 1.0;
      for (int d = 0, rest = corner; d < N; ++d, rest /= side_) {
        const int offset = rest % side_ - spec_.quality;
        point[d] = cell[d] + offset;
        v[d] = static_cast<double>(offset) - f[d];
        const double t = weight_scale_ * std::abs(v[d]);
        w[d] = falloff(t);
        dw[d] = weight_scale_ * (v[d] < 0.0 ? -falloff_slope(t) : falloff_slope(t));
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
      if (varying)
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
