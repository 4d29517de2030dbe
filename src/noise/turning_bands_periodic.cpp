// The periodic form of turning-bands noise, for the torus [0,1)^N (noise/turning_bands.hpp says how
// it is built and why).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/noise/noise_domain.hpp"
#include "dfvn/noise/turning_bands.hpp"
#include "dfvn/noise/turning_bands_kernel.hpp"

namespace dfvn {
namespace {

// v rounded to the nearest vector with even entries; 2 e_j (with w's sign) along w's largest
// coordinate if that is the zero vector.
template <int N>
Vec<N> even_knot_vector(const Vec<N>& v) {
  Vec<N> out;
  for (int j = 0; j < N; ++j) out[j] = 2.0 * std::round(0.5 * v[j]);
  if (out.isZero()) {
    int largest = 0;
    v.cwiseAbs().maxCoeff(&largest);
    out[largest] = v[largest] < 0.0 ? -2.0 : 2.0;
  }
  return out;
}

// The knot vectors of every band for the scale s' (one row per band).
template <int N, int kBands>
Eigen::Matrix<double, kBands, N> knot_vectors(const Eigen::Matrix<double, kBands, N>& frame_rows, double scale) {
  Eigen::Matrix<double, kBands, N> v;
  for (int b = 0; b < kBands; ++b) v.row(b) = even_knot_vector<N>(Vec<N>(scale * frame_rows.row(b).transpose())).transpose();
  return v;
}

// Candidate scales s' = s * 2^(k / 64), k = -64..64: the one whose mean |V_b|^2 is nearest s^2 (the
// nearer s' on a tie), so that the realised frequency follows the asked one.
constexpr int kScaleSteps = 64;

}  // namespace

template <int N>
TurningBandsNoise<N>::TurningBandsNoise(std::uint64_t seed, Periodic periodic, Simd simd, double phase)
    : periodic_(true), kernel_(Kernel::template choose<true>(simd, phase != 0.0)) {
  if (!(periodic.frequency >= kMinNoiseFrequency && periodic.frequency <= kMaxPeriodicFrequency))
    throw std::invalid_argument(fmt::format("a periodic noise's frequency must be in [2^-50, 2^20] cycles per unit length, got {:g}",
                                            periodic.frequency));
  draw_bands(seed, phase);
  const Eigen::Matrix<double, kBands, N> frame_rows = directions();
  const BandMoments m = quintic_band_moments();
  const double aperiodic_wavenumber = std::sqrt(m.slope2 / m.value2);
  const double knots_per_length = 2.0 * std::numbers::pi * periodic.frequency / aperiodic_wavenumber;  // s
  double best_scale = knots_per_length, best_error = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= 2 * kScaleSteps; ++k) {
    const int step = k % 2 == 0 ? k / 2 : -(k + 1) / 2;  // 0, -1, 1, -2, 2, ...: the nearer scale first
    const double scale = knots_per_length * std::exp2(static_cast<double>(step) / kScaleSteps);
    const double mean2 = knot_vectors<N, kBands>(frame_rows, scale).rowwise().squaredNorm().mean();
    const double error = std::abs(mean2 - knots_per_length * knots_per_length);
    if (error < best_error) best_error = error, best_scale = scale;
  }
  const Eigen::Matrix<double, kBands, N> knots = knot_vectors<N, kBands>(frame_rows, best_scale);
  set_rows(knots);
  // L_b: the lowest set bit of the entries' OR, which is 2 or more since every entry is even.
  for (int b = 0; b < kBands; ++b) {
    std::uint64_t bits = 0;
    for (int j = 0; j < N; ++j) bits |= static_cast<std::uint64_t>(std::abs(knots(b, j)));
    knot_masks_[b] = static_cast<std::int64_t>((bits & (~bits + 1)) - 1);
  }
  // Slopes at neighbouring knots are independent (L_b >= 2), so each band has the aperiodic moments
  // along its coordinate, and |grad p_b| = |p'_b| |V_b|: k_eff^2 = (E p'^2 / E p^2) mean_b |V_b|^2.
  const double mean_knots2 = knots.rowwise().squaredNorm().mean();
  wavenumber_ = aperiodic_wavenumber * std::sqrt(mean_knots2);
  // The aperiodic amplitude with sigma^2 = E p'^2 mean |V_b|^2, as if the gradients were isotropic;
  // the field measures the exact normalisation of its periodic functions (field/dfvn_field.hpp).
  const double factorial = std::tgamma(N + 1.0);
  amplitude_ = std::sqrt(N / (m.slope2 * mean_knots2 * std::pow(factorial, 1.0 / (N - 1))));
}

template TurningBandsNoise<2>::TurningBandsNoise(std::uint64_t, Periodic, Simd, double);
template TurningBandsNoise<3>::TurningBandsNoise(std::uint64_t, Periodic, Simd, double);
template TurningBandsNoise<4>::TurningBandsNoise(std::uint64_t, Periodic, Simd, double);
template TurningBandsNoise<5>::TurningBandsNoise(std::uint64_t, Periodic, Simd, double);
template TurningBandsNoise<6>::TurningBandsNoise(std::uint64_t, Periodic, Simd, double);
template TurningBandsNoise<7>::TurningBandsNoise(std::uint64_t, Periodic, Simd, double);
template TurningBandsNoise<8>::TurningBandsNoise(std::uint64_t, Periodic, Simd, double);

}  // namespace dfvn
