#include "noise/turning_bands.hpp"

#include <cmath>

#include "core/hash.hpp"
#include "noise/quintic_fade.hpp"
#include "noise/random_frame.hpp"

namespace dfvn {
namespace {

// Slope of a band at integer knot j, uniform in [-1, 1): one SplitMix64 finaliser of the band's key
// plus the knot times an odd constant (a bijection of j for each key).
inline double knot_slope(std::uint64_t key, std::int64_t j) {
  const std::uint64_t h = mix64(key + static_cast<std::uint64_t>(j) * kGoldenGamma);
  return static_cast<double>(static_cast<std::int64_t>(h)) * 0x1.0p-63;
}

// Value and slope of every band at its coordinate t_b (the profiles p(t_b) and p'(t_b)): two hashes
// and two polynomials per band, the bulk of an evaluation. With AVX-512 (64-bit multiplies and integer
// conversions in vectors) GCC runs the loop 8 bands at a time. Both builds do the same operations in
// the same order on every band, and this file is compiled without fused multiply-adds
// (CMakeLists.txt), so they give the same bits. (Moving the matrix-vector products into the kernel as
// well was no faster with AVX-512 and slower without.)
template <int kCount>
[[gnu::always_inline]] inline void band_profiles(const double* __restrict t, const std::uint64_t* __restrict keys,
                                                 double* __restrict value, double* __restrict slope) {
  for (int b = 0; b < kCount; ++b) {
    // floor by truncation: exact while |t| < 2^63, far beyond the range where t has a fraction at all.
    auto cell = static_cast<std::int64_t>(t[b]);
    cell -= static_cast<std::int64_t>(t[b] < static_cast<double>(cell));
    const double u = t[b] - static_cast<double>(cell);
    const double g0 = knot_slope(keys[b], cell), g1 = knot_slope(keys[b], cell + 1);
    const double s = quintic_fade(u), ds = quintic_fade_slope(u);
    value[b] = g0 * u * (1.0 - s) + g1 * (u - 1.0) * s;
    slope[b] = g0 * (1.0 - s - u * ds) + g1 * (s + (u - 1.0) * ds);
  }
}

template <int kCount>
void band_profiles_baseline(const double* t, const std::uint64_t* keys, double* value, double* slope) {
  band_profiles<kCount>(t, keys, value, slope);
}

using BandProfiles = void (*)(const double* t, const std::uint64_t* keys, double* value, double* slope);

#if defined(__x86_64__)
template <int kCount>
[[gnu::target("avx512f,avx512dq,avx512vl")]] void band_profiles_avx512(const double* t, const std::uint64_t* keys,
                                                                       double* value, double* slope) {
  band_profiles<kCount>(t, keys, value, slope);
}
#endif

// The AVX-512 build where asked for and the CPU has every extension it is compiled for, else the baseline.
template <int kCount>
BandProfiles choose_band_profiles(Simd simd) {
#if defined(__x86_64__)
  if (simd == Simd::best && cpu_has_avx512()) return &band_profiles_avx512<kCount>;
#endif
  (void)simd;
  return &band_profiles_baseline<kCount>;
}

// Lanes of the turning-bands stream: per band (index = band) the key and the offset; per frame
// (index = function * 2 + frame) the Gaussian entries from lane kFrameLane on.
constexpr std::uint64_t kKeyLane = 0, kOffsetLane = 1, kFrameLane = 16;
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
TurningBandsNoise<N>::TurningBandsNoise(std::uint64_t seed, Simd simd)
    : profiles_(choose_band_profiles<kBands>(simd)) {
  for (int i = 0; i < N - 1; ++i)
    for (int frame = 0; frame < 2; ++frame) {
      const auto q = random_frame<N>(seed, Stream::turning_bands, kFrameIndexBase + 2 * static_cast<std::uint64_t>(i) + frame, kFrameLane);
      directions_.template block<N, N>(i * kBandsPerFunction + frame * N, 0) = q.transpose();
    }
  for (int b = 0; b < kBands; ++b) {
    keys_[b] = random_bits(seed, Stream::turning_bands, static_cast<std::uint64_t>(b), kKeyLane);
    offsets_[b] = random_unit(seed, Stream::turning_bands, static_cast<std::uint64_t>(b), kOffsetLane);
  }
}

template <int N>
NoiseSample<N, N - 1> TurningBandsNoise<N>::evaluate(const Vec<N>& x) const {
  // Band coordinates t_b = w_b . x + o_b for all bands at once (one matrix-vector product).
  const Eigen::Matrix<double, kBands, 1> t = directions_ * x + offsets_;
  Eigen::Matrix<double, kBands, 1> value, slope;
  profiles_(t.data(), keys_.data(), value.data(), slope.data());
  const double norm = 1.0 / std::sqrt(static_cast<double>(kBandsPerFunction));
  NoiseSample<N, N - 1> out;
  for (int i = 0; i < N - 1; ++i) {
    const int first = i * kBandsPerFunction;
    out.value[i] = norm * value.template segment<kBandsPerFunction>(first).sum();
    // grad n_i = K^(-1/2) sum_k p'_ik w_ik = K^(-1/2) W_i^T p'_i.
    out.gradient[i].noalias() =
        norm * directions_.template middleRows<kBandsPerFunction>(first).transpose() * slope.template segment<kBandsPerFunction>(first);
  }
  return out;
}

template <int N>
double TurningBandsNoise<N>::wavenumber() const {
  // |w| = 1 and the bands are independent: E|grad n|^2 / E n^2 = E p'^2 / E p^2.
  const BandMoments m = quintic_band_moments();
  return std::sqrt(m.slope2 / m.value2);
}

template <int N>
double TurningBandsNoise<N>::amplitude() const {
  // RMS |c| of the gradients A grad n_i is sqrt(N! (A^2 sigma^2 / N)^(N-1)); set it to 1.
  const double sigma2 = quintic_band_moments().slope2;
  const double factorial = std::tgamma(N + 1.0);
  return std::sqrt(N / (sigma2 * std::pow(factorial, 1.0 / (N - 1))));
}

template class TurningBandsNoise<2>;
template class TurningBandsNoise<3>;
template class TurningBandsNoise<4>;
template class TurningBandsNoise<5>;
template class TurningBandsNoise<6>;
template class TurningBandsNoise<7>;
template class TurningBandsNoise<8>;

}  // namespace dfvn
