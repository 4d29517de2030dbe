// Turning-bands noise: each function is a sum of one-dimensional C2 gradient noises along the rows of
// two random orthonormal frames. Healthy in every dimension (the DFVN field does not collapse).
#pragma once

#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "dfvn/core/dimension.hpp"
#include "dfvn/core/simd.hpp"
#include "dfvn/noise/noise_functions.hpp"

namespace dfvn {

// n_i(x) = K^(-1/2) sum_{k<K} p_ik(w_ik . x + o_ik), i = 0..N-2, K = 2N bands per function (Matheron's
// turning bands; the recipe of data/NOISE_STUDY.md):
// - w_ik: the 2N rows of two seeded random orthonormal frames of function i (Haar-distributed, from the
//   QR factorisation of a Gaussian matrix). Two full frames make sum_k w_ik w_ik^T = 2 I, so every
//   gradient is isotropic: E[grad n_i grad n_i^T] = (sigma^2 / N) I with sigma^2 = E p'^2. Directions
//   drawn one by one would leave each function anisotropic (the study saw eigenvalue ratios of 30 in 8D).
// - p_ik: 1D gradient noise with a slope hashed uniformly in [-1, 1] at every integer knot and the
//   quintic fade s(u) = 6u^5 - 15u^4 + 10u^3 between knots, p(u) = g0 u (1 - s) + g1 (u - 1) s. s' and
//   s'' vanish at u = 0 and 1, so p is C2: value 0, slope g_j and curvature 0 at every knot.
// - o_ik: an offset uniform in [0, 1), so that the knots of different bands do not meet at the origin.
// Every band of every function has its own hash key: the N-1 functions share nothing, so they are
// independent and E|cross(grad n_i)|^2 = N! (sigma^2 / N)^(N-1) in closed form (Cauchy-Binet over
// uncorrelated gradient coordinates), which gives amplitude() without measurement.
// Free of transcendental functions: per evaluation 2N(N-1) bands, each a dot product, two hashes and a
// polynomial.
//
// The phase alpha (rotating gradients, McEwan & Gustavson's flow noise, seeds/001): a 1D gradient is a
// scalar slope, and there is no plane of a line to rotate in. So every knot carries a 2-vector (a, b) of
// two independent seeded slopes, each uniform in [-1, 1) (a is the knot's slope at alpha = 0), and its
// slope at alpha is that vector's component along (cos alpha, sin alpha): g(alpha) = a cos alpha +
// b sin alpha. E g^2 = (1/3)(cos^2 + sin^2) = 1/3 at every alpha (no rescaling is needed) and slopes of
// different knots stay independent with zero mean, so E p^2, E p'^2, k_eff and amplitude() are those of
// alpha = 0 exactly; E[g(0) g(alpha)] / E g^2 = cos alpha, so the noise's correlation with its alpha = 0
// self is cos alpha; g(alpha + pi) = -g(alpha) and the period is 2 pi. For a fixed alpha the profile is
// the same quintic form in the knot slopes, so p and every n_i stay C2. (The slope's distribution is no
// longer uniform away from multiples of pi / 2: only its moments up to the second are kept.) Phase 0
// runs the phase-free kernel, bit for bit the noise before phases existed.
//
// The periodic form (the torus [0,1)^N, TurningBandsNoise(seed, Periodic{F})) has period 1 along every
// axis and is evaluated at x itself (the field's scale is 1): band b is p_b(V_b . x + o_b) with an
// integer knot vector V_b and knot slopes hashed from the knot index modulo L_b, the largest power of
// two that divides every entry of V_b. Shifting x by e_j shifts the band coordinate by V_bj, a multiple
// of L_b, so every band, and every n_i with its gradient, repeats. V_b = 2 round(s' w_b / 2), the frame row w_b scaled by s' ~ s = 2 pi F / k_eff
// (the knots per unit length of the aperiodic form at F cycles per unit length) and rounded to even
// entries (2 e_j along w_b's largest coordinate if that rounds to 0): even entries make L_b >= 2, so
// neighbouring knots keep independent slopes and the band's spectrum is the aperiodic one's (with
// L_b = 1 a band would be one fixed wave, of k_eff 6.39 instead of 3.62 per knot). s' is the scale
// whose mean |V_b|^2 comes nearest s^2, so that the realised frequency (wavenumber() / 2 pi) is close
// to F; it cannot go below one knot pair per unit length (F ~ 1.15). Rounding makes the directions
// only roughly isotropic, the more so the lower F: at F ~ 1 most V_b are 2 e_j.
template <int N>
class TurningBandsNoise final : public NoiseFunctions<N> {
 public:
  static_assert(N >= kMinDimension && N <= kMaxDimension);
  static constexpr int kBandsPerFunction = 2 * N;
  static constexpr int kBands = (N - 1) * kBandsPerFunction;

  // `simd`: which build of the evaluation kernel runs (core/simd.hpp); every build gives the same bits.
  explicit TurningBandsNoise(std::uint64_t seed, Simd simd = Simd::best, double phase = 0.0);
  // The periodic form at about `frequency` cycles per unit length (throws std::invalid_argument outside
  // [kMinNoiseFrequency, kMaxPeriodicFrequency]).
  struct Periodic {
    double frequency;
  };
  TurningBandsNoise(std::uint64_t seed, Periodic periodic, Simd simd = Simd::best, double phase = 0.0);
  // Integer knot entries stay exact in doubles, and band coordinates far below 2^52, up to this.
  static constexpr double kMaxPeriodicFrequency = 0x1p20;

  NoiseSample<N, N - 1> evaluate(const Vec<N>& x) const override;
  double wavenumber() const override;
  double amplitude() const override;

  // One row per band; band b = i * kBandsPerFunction + k belongs to function i. Unit frame rows, or the
  // integer knot vectors V_b of the periodic form.
  Eigen::Matrix<double, kBands, N> directions() const;
  bool periodic() const { return periodic_; }
  double phase() const { return phase_; }

 private:
  // The evaluation kernel works on vectors of up to 8 doubles (AVX-512): 8 bands at a time for the
  // band coordinates and profiles, one whole direction (N <= 8 coordinates, zero-padded) for a gradient.
  static constexpr int kLanes = 8;
  static constexpr int kPaddedBands = (kBands + kLanes - 1) / kLanes * kLanes;
  struct Kernel;  // its AVX-512 and baseline builds (turning_bands.cpp)

  // The bands in the two layouts the kernel reads; padding bands have zero directions, offsets and keys.
  std::array<std::array<double, kPaddedBands>, N> columns_;  // columns_[j][b] = w_b[j]
  std::array<double, kPaddedBands> offsets_;
  std::array<std::array<double, kLanes>, kBands> rows_;    // rows_[b] = w_b, zero-padded
  std::array<std::uint64_t, kPaddedBands> keys_{};
  std::array<std::int64_t, kPaddedBands> knot_masks_{};  // periodic form: L_b - 1 (0 in padding bands)
  std::array<std::uint64_t, kPaddedBands> phase_keys_{};  // the keys of the knots' second slopes b
  double phase_ = 0.0, cos_phase_ = 1.0, sin_phase_ = 0.0;
  bool periodic_ = false;
  double wavenumber_ = 0.0, amplitude_ = 0.0;
  void (*kernel_)(const TurningBandsNoise& noise, const Vec<N>& x, NoiseSample<N, N - 1>& out);

  // The frames and per-band keys and offsets, shared by both forms.
  void draw_bands(std::uint64_t seed, double phase);
  void set_rows(const Eigen::Matrix<double, kBands, N>& rows);
};

// Moments of one band, E p^2 and E p'^2, over a uniform position and slopes uniform in [-1, 1].
struct BandMoments {
  double value2;
  double slope2;
};
BandMoments quintic_band_moments();

extern template class TurningBandsNoise<2>;
extern template class TurningBandsNoise<3>;
extern template class TurningBandsNoise<4>;
extern template class TurningBandsNoise<5>;
extern template class TurningBandsNoise<6>;
extern template class TurningBandsNoise<7>;
extern template class TurningBandsNoise<8>;

}  // namespace dfvn
