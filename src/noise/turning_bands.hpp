// Turning-bands noise: each function is a sum of one-dimensional C2 gradient noises along the rows of
// two random orthonormal frames. Healthy in every dimension (the DFVN field does not collapse).
#pragma once

#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "core/dimension.hpp"
#include "core/simd.hpp"
#include "noise/noise_functions.hpp"

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
// Not periodic and free of transcendental functions: per evaluation 2N(N-1) bands, each a dot product,
// two hashes and a polynomial.
template <int N>
class TurningBandsNoise final : public NoiseFunctions<N> {
 public:
  static_assert(N >= kMinDimension && N <= kMaxDimension);
  static constexpr int kBandsPerFunction = 2 * N;
  static constexpr int kBands = (N - 1) * kBandsPerFunction;

  // `simd`: which build of the evaluation kernel runs (core/simd.hpp); every build gives the same bits.
  explicit TurningBandsNoise(std::uint64_t seed, Simd simd = Simd::best);

  NoiseSample<N, N - 1> evaluate(const Vec<N>& x) const override;
  double wavenumber() const override;
  double amplitude() const override;

  // One row per band; band b = i * kBandsPerFunction + k belongs to function i.
  Eigen::Matrix<double, kBands, N> directions() const;

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
  void (*kernel_)(const TurningBandsNoise& noise, const Vec<N>& x, NoiseSample<N, N - 1>& out);
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
