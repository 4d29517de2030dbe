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
// and two polynomials per band. With AVX-512 (64-bit multiplies and integer conversions in vectors)
// GCC runs the loop 8 bands at a time.
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

// (Through a reference: a function returning a vector would have a different ABI in each build.)
template <typename V>
[[gnu::always_inline]] inline const V& load_lanes(V& v, const double* p) {
  __builtin_memcpy(&v, p, sizeof v);
  return v;
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

// One evaluation: band coordinates, profiles, and the sums into values and gradients, on vectors.
// (With Eigen's products around a vector band loop, the products took as long as the loop.) Built
// twice, for AVX-512 and for the baseline; this file is compiled without fused multiply-adds
// (CMakeLists.txt), so the builds give the same bits.
template <int N>
struct TurningBandsNoise<N>::Kernel {
  template <int W>
  [[gnu::always_inline]] static inline void run(const TurningBandsNoise& noise, const Vec<N>& x,
                                                NoiseSample<N, N - 1>& out) {
    static_assert(kLanes % W == 0);
    // W doubles in one vector register: 8 with AVX-512, 2 with SSE2 (the baseline). Every lane sees
    // the same operations in the same order whatever W is.
    typedef double Lanes __attribute__((vector_size(8 * W)));
    constexpr int kUsedBands = (kBands + W - 1) / W * W;  // <= kPaddedBands
    double t[kUsedBands], value[kUsedBands], slope[kUsedBands];
    // t_b = w_b . x + o_b, W bands per vector, summed as ((w_b0 x_0 + w_b1 x_1) + ...) + o_b.
    Lanes in;
    for (int v = 0; v < kUsedBands; v += W) {
      Lanes sum = load_lanes(in, &noise.columns_[0][v]) * x[0];
      for (int j = 1; j < N; ++j) sum += load_lanes(in, &noise.columns_[j][v]) * x[j];
      sum += load_lanes(in, &noise.offsets_[v]);
      __builtin_memcpy(t + v, &sum, sizeof sum);
    }
    band_profiles<kUsedBands>(t, noise.keys_.data(), value, slope);
    // n_i = K^(-1/2) sum_k p_ik and grad n_i = K^(-1/2) sum_k p'_ik w_ik, k in order; the
    // directions' first N coordinates (zero-padded) in ceil(N / W) vectors.
    const double norm = 1.0 / std::sqrt(static_cast<double>(kBandsPerFunction));
    constexpr int kChunks = (N + W - 1) / W;
    for (int i = 0; i < N - 1; ++i) {
      double sum = 0.0;
      Lanes gradient[kChunks] = {};
      for (int k = 0; k < kBandsPerFunction; ++k) {
        const int b = i * kBandsPerFunction + k;
        sum += value[b];
        for (int c = 0; c < kChunks; ++c) gradient[c] += slope[b] * load_lanes(in, &noise.rows_[b][c * W]);
      }
      out.value[i] = norm * sum;
      for (int j = 0; j < N; ++j) out.gradient[i][j] = norm * gradient[j / W][j % W];
    }
  }

  static void baseline(const TurningBandsNoise& noise, const Vec<N>& x, NoiseSample<N, N - 1>& out) {
    run<2>(noise, x, out);
  }

#if defined(__x86_64__)
  [[gnu::target("avx512f,avx512dq,avx512vl")]] static void avx512(const TurningBandsNoise& noise, const Vec<N>& x,
                                                                  NoiseSample<N, N - 1>& out) {
    run<8>(noise, x, out);
  }
#endif

  // The AVX-512 build where asked for and the CPU has every extension it is compiled for, else the baseline.
  static auto choose(Simd simd) -> decltype(&baseline) {
#if defined(__x86_64__)
    if (simd == Simd::best && cpu_has_avx512()) return &avx512;
#endif
    (void)simd;
    return &baseline;
  }
};

template <int N>
TurningBandsNoise<N>::TurningBandsNoise(std::uint64_t seed, Simd simd) : kernel_(Kernel::choose(simd)) {
  for (auto& row : rows_) row.fill(0.0);
  for (int i = 0; i < N - 1; ++i)
    for (int frame = 0; frame < 2; ++frame) {
      // The frame's columns are the directions of N consecutive bands.
      const auto q = random_frame<N>(seed, Stream::turning_bands, kFrameIndexBase + 2 * static_cast<std::uint64_t>(i) + frame, kFrameLane);
      for (int r = 0; r < N; ++r)
        for (int j = 0; j < N; ++j) rows_[i * kBandsPerFunction + frame * N + r][j] = q(j, r);
    }
  for (auto& column : columns_) column.fill(0.0);
  offsets_.fill(0.0);
  for (int b = 0; b < kBands; ++b) {
    keys_[b] = random_bits(seed, Stream::turning_bands, static_cast<std::uint64_t>(b), kKeyLane);
    offsets_[b] = random_unit(seed, Stream::turning_bands, static_cast<std::uint64_t>(b), kOffsetLane);
    for (int j = 0; j < N; ++j) columns_[j][b] = rows_[b][j];
  }
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
