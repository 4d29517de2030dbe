#include "dfvn/noise/gradient_noise.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "dfvn/core/hash.hpp"
#include "dfvn/noise/quintic_fade.hpp"
#include "dfvn/noise/random_frame.hpp"

namespace dfvn {
namespace {

// Lanes of the gradient-noise stream, per function (index = function): the hash key, the offset
// components from kOffsetLane on, and the Gaussian entries of the rotation from kFrameLane on.
constexpr std::uint64_t kKeyLane = 0, kOffsetLane = 1, kFrameLane = 16;
// The key of the phase's second gradients, past the offset's lanes (kOffsetLane + d < 9) and before the frame's.
constexpr std::uint64_t kPhaseKeyLane = 12;

// Exact arithmetic on polynomials in u with double coefficients (all of them small integers or
// their ratios here, so the integrals below are exact up to one rounding per term).
using Polynomial = std::vector<double>;  // coefficient of u^k at index k

Polynomial multiply(const Polynomial& a, const Polynomial& b) {
  Polynomial product(a.size() + b.size() - 1, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) product[i + j] += a[i] * b[j];
  return product;
}

Polynomial derivative(const Polynomial& a) {
  Polynomial d(a.size() > 1 ? a.size() - 1 : 1, 0.0);
  for (std::size_t k = 1; k < a.size(); ++k) d[k - 1] = static_cast<double>(k) * a[k];
  return d;
}

double integral_over_unit_interval(const Polynomial& a) {  // int_0^1 a(u) du
  double sum = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) sum += a[k] / static_cast<double>(k + 1);
  return sum;
}

double integral_of_square(const Polynomial& a) { return integral_over_unit_interval(multiply(a, a)); }

}  // namespace

GradientNoiseMoments quintic_gradient_noise_moments(int dimension) {
  // Write n = sum_{c,k} g_ck phi_ck(u) with phi_ck = w_c(u) (u_k - c_k). The g_ck are independent with
  // mean 0 and variance 1/3 (uniform in [-1, 1]), and space averages u uniformly over the unit cell:
  //   E n^2       = (1/3) sum_{c,k} int phi_ck^2,   E|grad n|^2 = (1/3) sum_{c,k} int |grad phi_ck|^2.
  // phi_ck is a product over axes of one-dimensional factors: a_{c_d}(u_d) for d != k (a_0 = 1 - s,
  // a_1 = s) and b_{c_k}(u_k) = a_{c_k}(u_k) (u_k - c_k) on axis k. Summing each axis over c_d in {0, 1}:
  //   int a_0^2 + a_1^2 = 2 A,  int a_0'^2 + a_1'^2 = 2 A',  int b_0^2 + b_1^2 = 2 B,  int b_0'^2 + b_1'^2 = 2 B'
  // (the two terms are equal by the symmetry u -> 1 - u), with A = int s^2, A' = int s'^2,
  // B = int ((1 - s) u)^2, B' = int (((1 - s) u)')^2 over [0, 1]. Hence
  //   E n^2       = (N / 3) (2A)^(N-1) (2B),
  //   E|grad n|^2 = (N / 3) [(2A)^(N-1) (2B') + (N - 1) (2A)^(N-2) (2A') (2B)]
  // (the derivative falls on axis k, or on one of the N - 1 others). A = 181/462, A' = 10/7,
  // B = 535/18018, B' = 30/77; in 2D E n^2 = 0.03102 and E|grad n|^2 = 0.5202. A rotation R_i leaves
  // both unchanged.
  if (dimension < 1) throw std::invalid_argument("gradient noise needs a dimension >= 1");
  const Polynomial fade = {0.0, 0.0, 0.0, 10.0, -15.0, 6.0};  // s(u)
  const Polynomial one_minus_fade = {1.0, 0.0, 0.0, -10.0, 15.0, -6.0};
  const Polynomial b = multiply(one_minus_fade, Polynomial{0.0, 1.0});  // (1 - s(u)) u
  const double a2 = 2.0 * integral_of_square(fade), da2 = 2.0 * integral_of_square(derivative(fade));
  const double b2 = 2.0 * integral_of_square(b), db2 = 2.0 * integral_of_square(derivative(b));
  const double n = dimension;
  const double value2 = (n / 3.0) * std::pow(a2, n - 1) * b2;
  const double gradient2 = (n / 3.0) * (std::pow(a2, n - 1) * db2 + (n - 1) * std::pow(a2, n - 2) * da2 * b2);
  return {value2, gradient2};
}

template <int N>
QuinticGradientNoise<N>::QuinticGradientNoise(std::uint64_t seed, double phase)
    : phase_(phase), cos_phase_(std::cos(phase)), sin_phase_(std::sin(phase)) {
  for (int i = 0; i < N - 1; ++i) {
    const auto index = static_cast<std::uint64_t>(i);
    keys_[i] = random_bits(seed, Stream::gradient_noise, index, kKeyLane);
    phase_keys_[i] = random_bits(seed, Stream::gradient_noise, index, kPhaseKeyLane);
    for (int d = 0; d < N; ++d)
      offsets_[i][d] = random_unit(seed, Stream::gradient_noise, index, kOffsetLane + static_cast<std::uint64_t>(d));
    rotations_[i] = i == 0 ? Eigen::Matrix<double, N, N>::Identity()
                           : random_frame<N>(seed, Stream::gradient_noise, index, kFrameLane);
  }
}

namespace {

// Odd multipliers that spread the lattice coordinates over 64 bits before one mixing: distinct lattice
// points give distinct sums (unless their coordinates differ by multiples of 2^64 / gcd), and
// SplitMix64's finaliser then decorrelates neighbours.
constexpr std::uint64_t axis_multiplier(int axis) { return mix64(kGoldenGamma * static_cast<std::uint64_t>(axis + 1)) | 1u; }

}  // namespace

template <int N>
std::uint64_t QuinticGradientNoise<N>::lattice_multiplier(int axis) {
  return axis_multiplier(axis);
}

template <int N>
Vec<N> QuinticGradientNoise<N>::lattice_gradient(int function, const std::array<std::int64_t, N>& lattice) const {
  return hashed_gradient(keys_[function], lattice);
}

template <int N>
Vec<N> QuinticGradientNoise<N>::rotated_lattice_gradient(int function, const std::array<std::int64_t, N>& lattice) const {
  const Vec<N> p = hashed_gradient(keys_[function], lattice);
  Vec<N> q = hashed_gradient(phase_keys_[function], lattice);
  const double p2 = p.squaredNorm();
  if (!(p2 > 0.0)) return p;  // the zero gradient (probability 2^-31N) stays zero
  q -= (q.dot(p) / p2) * p;
  const double q2 = q.squaredNorm();
  // q parallel to p (probability ~0 for continuous components): turn only along p, still 2 pi-periodic.
  if (!(q2 > 1e-24 * p2)) return cos_phase_ * p;
  return cos_phase_ * p + (sin_phase_ * std::sqrt(p2 / q2)) * q;
}

template <int N>
Vec<N> QuinticGradientNoise<N>::hashed_gradient(std::uint64_t key, const std::array<std::int64_t, N>& lattice) {
  std::uint64_t h = key;
  for (int d = 0; d < N; ++d) h += static_cast<std::uint64_t>(lattice[d]) * axis_multiplier(d);
  // Two components per 64-bit word: each 32-bit half read as a signed integer and scaled to [-1, 1).
  Vec<N> g;
  for (int k = 0; k < N; k += 2) {
    const std::uint64_t bits = mix64(h + static_cast<std::uint64_t>(k / 2 + 1) * kGoldenGamma);
    g[k] = static_cast<double>(static_cast<std::int32_t>(static_cast<std::uint32_t>(bits))) * 0x1.0p-31;
    if (k + 1 < N) g[k + 1] = static_cast<double>(static_cast<std::int32_t>(static_cast<std::uint32_t>(bits >> 32))) * 0x1.0p-31;
  }
  return g;
}

template <int N>
NoiseSample<N, N - 1> QuinticGradientNoise<N>::evaluate(const Vec<N>& x) const {
  NoiseSample<N, N - 1> out;
  for (int i = 0; i < N - 1; ++i) {
    const Vec<N> y = rotations_[i] * x + offsets_[i];
    std::array<std::int64_t, N> cell;
    Vec<N> u;
    // Per axis the two weights (1 - s, s) and their derivatives (-s', s').
    std::array<std::array<double, 2>, N> weight, weight_slope;
    for (int d = 0; d < N; ++d) {
      cell[d] = static_cast<std::int64_t>(std::floor(y[d]));
      u[d] = y[d] - static_cast<double>(cell[d]);
      const double s = quintic_fade(u[d]), ds = quintic_fade_slope(u[d]);
      weight[d] = {1.0 - s, s};
      weight_slope[d] = {-ds, ds};
    }
    double value = 0.0;
    Vec<N> gradient = Vec<N>::Zero();  // with respect to y
    for (int corner = 0; corner < kCorners; ++corner) {
      std::array<std::int64_t, N> lattice;
      Vec<N> offset;  // u - c
      // prefix[d] = product of the weights of axes < d; the suffix product runs backwards below.
      std::array<double, N + 1> prefix;
      prefix[0] = 1.0;
      for (int d = 0; d < N; ++d) {
        const int bit = (corner >> d) & 1;
        lattice[d] = cell[d] + bit;
        offset[d] = u[d] - bit;
        prefix[d + 1] = prefix[d] * weight[d][bit];
      }
      const Vec<N> g = phase_ != 0.0 ? rotated_lattice_gradient(i, lattice) : lattice_gradient(i, lattice);
      const double projection = g.dot(offset);
      const double w = prefix[N];
      // grad (w g.(u - c)) = w g + (g.(u - c)) grad w, with d w / d u_d = w_d' prod_{e != d} w_e.
      gradient += w * g;
      double suffix = 1.0;
      for (int d = N - 1; d >= 0; --d) {
        const int bit = (corner >> d) & 1;
        gradient[d] += projection * weight_slope[d][bit] * prefix[d] * suffix;
        suffix *= weight[d][bit];
      }
      value += w * projection;
    }
    out.value[i] = value;
    out.gradient[i].noalias() = rotations_[i].transpose() * gradient;  // chain rule through y = R x + o
  }
  return out;
}

template <int N>
double QuinticGradientNoise<N>::wavenumber() const {
  const GradientNoiseMoments m = quintic_gradient_noise_moments(N);
  return std::sqrt(m.gradient2 / m.value2);
}

template <int N>
double QuinticGradientNoise<N>::amplitude() const {
  // Each function's gradient has covariance (sigma^2 / N) I over space (the cube's reflections and
  // axis permutations map the noise's distribution to itself; a rotation keeps a multiple of I), and
  // the N - 1 gradients are independent (see the header). For independent columns with covariance
  // lambda I, every (N-1) x (N-1) minor has E det^2 = (N-1)! lambda^(N-1), and |c|^2 sums N of them
  // (Cauchy-Binet), so E|c|^2 = N! (sigma^2 / N)^(N-1). With gradients A grad n_i, set
  // N! (A^2 sigma^2 / N)^(N-1) = 1. In 2D this is A = 1 / sigma exactly, independence or not.
  const double sigma2 = quintic_gradient_noise_moments(N).gradient2;
  const double factorial = std::tgamma(N + 1.0);
  return std::sqrt(N / (sigma2 * std::pow(factorial, 1.0 / (N - 1))));
}

template class QuinticGradientNoise<2>;
template class QuinticGradientNoise<3>;
template class QuinticGradientNoise<4>;
template class QuinticGradientNoise<5>;
template class QuinticGradientNoise<6>;
template class QuinticGradientNoise<7>;
template class QuinticGradientNoise<8>;

}  // namespace dfvn
