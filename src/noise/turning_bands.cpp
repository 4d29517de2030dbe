#include "dfvn/noise/turning_bands.hpp"

#include <cmath>

#include "dfvn/core/hash.hpp"
#include "dfvn/noise/random_frame.hpp"
#include "dfvn/noise/turning_bands_kernel.hpp"

namespace dfvn {
namespace {

// Lanes of the turning-bands stream: per band (index = band) the key and the offset; per frame
// (index = function * 2 + frame) the Gaussian entries from lane kFrameLane on.
constexpr std::uint64_t kKeyLane = 0, kOffsetLane = 1, kPhaseKeyLane = 2, kFrameLane = 16;
constexpr std::uint64_t kFrameIndexBase = 1ULL << 32;  // frames never share an index with a band

}  // namespace

BandMoments quintic_band_moments() {
  // p = g0 a(u) + g1 b(u) with a = u (1 - s), b = (u - 1) s; the slopes are independent with
  // E g^2 = 1/3, so E p^2 = (1/3) int_0^1 (a^2 + b^2) du and E p'^2 = (1/3) int_0^1 (a'^2 + b'^2) du.
  // Integrating these polynomials (degree <= 12) exactly in rational arithmetic gives 535/27027 and
  // 20/77: k_eff = sqrt(E p'^2 / E p^2) = 3.622 radians per knot spacing. The test
  // TurningBands.BandMomentsHaveTheirClosedForms re-derives both by quadrature of fade().
  return {535.0 / 27027.0, 20.0 / 77.0};
}

template <int N>
void TurningBandsNoise<N>::draw_bands(std::uint64_t seed, double phase) {
  Eigen::Matrix<double, kBands, N> rows;
  for (int i = 0; i < N - 1; ++i)
    for (int frame = 0; frame < 2; ++frame) {
      // The frame's columns are the directions of N consecutive bands.
      const auto q = random_frame<N>(seed, Stream::turning_bands, kFrameIndexBase + 2 * static_cast<std::uint64_t>(i) + frame, kFrameLane);
      for (int r = 0; r < N; ++r) rows.row(i * kBandsPerFunction + frame * N + r) = q.col(r).transpose();
    }
  set_rows(rows);
  offsets_.fill(0.0);
  for (int b = 0; b < kBands; ++b) {
    keys_[b] = random_bits(seed, Stream::turning_bands, static_cast<std::uint64_t>(b), kKeyLane);
    offsets_[b] = random_unit(seed, Stream::turning_bands, static_cast<std::uint64_t>(b), kOffsetLane);
    phase_keys_[b] = random_bits(seed, Stream::turning_bands, static_cast<std::uint64_t>(b), kPhaseKeyLane);
  }
  phase_ = phase;
  cos_phase_ = std::cos(phase);
  sin_phase_ = std::sin(phase);
}

template <int N>
void TurningBandsNoise<N>::set_rows(const Eigen::Matrix<double, kBands, N>& rows) {
  for (auto& row : rows_) row.fill(0.0);
  for (auto& column : columns_) column.fill(0.0);
  for (int b = 0; b < kBands; ++b)
    for (int j = 0; j < N; ++j) rows_[b][j] = columns_[j][b] = rows(b, j);
}

template <int N>
TurningBandsNoise<N>::TurningBandsNoise(std::uint64_t seed, Simd simd, double phase)
    : kernel_(Kernel::template choose<false>(simd, phase != 0.0)) {
  draw_bands(seed, phase);
  // |w| = 1 and the bands are independent: E|grad n|^2 / E n^2 = E p'^2 / E p^2.
  const BandMoments m = quintic_band_moments();
  wavenumber_ = std::sqrt(m.slope2 / m.value2);
  // RMS |c| of the gradients A grad n_i is sqrt(N! (A^2 sigma^2 / N)^(N-1)); set it to 1.
  const double factorial = std::tgamma(N + 1.0);
  amplitude_ = std::sqrt(N / (m.slope2 * std::pow(factorial, 1.0 / (N - 1))));
}

template <int N>
auto TurningBandsNoise<N>::directions() const -> Eigen::Matrix<double, kBands, N> {
  Eigen::Matrix<double, kBands, N> w;
  for (int b = 0; b < kBands; ++b)
    for (int j = 0; j < N; ++j) w(b, j) = rows_[b][j];
  return w;
}

template <int N>
NoiseSample<N, N - 1> TurningBandsNoise<N>::evaluate(const Vec<N>& x) const {
  NoiseSample<N, N - 1> out;
  kernel_(*this, x, out);
  return out;
}

template <int N>
double TurningBandsNoise<N>::wavenumber() const {
  return wavenumber_;
}

template <int N>
double TurningBandsNoise<N>::amplitude() const {
  return amplitude_;
}

template class TurningBandsNoise<2>;
template class TurningBandsNoise<3>;
template class TurningBandsNoise<4>;
template class TurningBandsNoise<5>;
template class TurningBandsNoise<6>;
template class TurningBandsNoise<7>;
template class TurningBandsNoise<8>;

}  // namespace dfvn
