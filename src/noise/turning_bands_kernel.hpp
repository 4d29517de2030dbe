// The turning-bands evaluation kernel (noise/turning_bands.hpp), shared by the aperiodic form
// (turning_bands.cpp) and the periodic one (turning_bands_periodic.cpp), each built for AVX-512 and for
// the baseline. Private (not installed): template internals of those two files.
#pragma once

#include <cmath>
#include <cstdint>

#include "dfvn/core/hash.hpp"
#include "dfvn/noise/quintic_fade.hpp"
#include "dfvn/noise/turning_bands.hpp"

namespace dfvn {
namespace turning_bands_detail {

// Slope of a band at integer knot j, uniform in [-1, 1): one SplitMix64 finaliser of the band's key
// plus the knot times an odd constant (a bijection of j for each key).
inline double knot_slope(std::uint64_t key, std::int64_t j) {
  const std::uint64_t h = mix64(key + static_cast<std::uint64_t>(j) * kGoldenGamma);
  return static_cast<double>(static_cast<std::int64_t>(h)) * 0x1.0p-63;
}

// Value and slope of every band at its coordinate t_b (the profiles p(t_b) and p'(t_b)): two hashes
// and two polynomials per band. kPeriodic: the knots are taken modulo the band's period L_b, a power
// of two, as knot & (L_b - 1). With AVX-512 (64-bit multiplies and integer conversions in vectors) GCC
// runs the loop 8 bands at a time.
// kPhase (a phase alpha != 0, TurningBandsNoise's `phase`): the slope at a knot is a cos alpha + b sin alpha,
// a from `keys` (the slope at alpha = 0) and b from `phase_keys`; without it the code is the phase-free one.
template <int kCount, bool kPeriodic, bool kPhase = false>
[[gnu::always_inline]] inline void band_profiles(const double* __restrict t, const std::uint64_t* __restrict keys,
                                                 const std::int64_t* __restrict knot_masks, double* __restrict value,
                                                 double* __restrict slope,
                                                 const std::uint64_t* __restrict phase_keys = nullptr,
                                                 double cos_phase = 1.0, double sin_phase = 0.0) {
  for (int b = 0; b < kCount; ++b) {
    // floor by truncation: exact while |t| < 2^63, far beyond the range where t has a fraction at all.
    auto cell = static_cast<std::int64_t>(t[b]);
    cell -= static_cast<std::int64_t>(t[b] < static_cast<double>(cell));
    const double u = t[b] - static_cast<double>(cell);
    std::int64_t knot0 = cell, knot1 = cell + 1;
    if constexpr (kPeriodic) {  // modulo a power of two: the low bits, negative cells included
      knot0 = cell & knot_masks[b];
      knot1 = (cell + 1) & knot_masks[b];
    }
    double g0 = knot_slope(keys[b], knot0), g1 = knot_slope(keys[b], knot1);
    if constexpr (kPhase) {
      g0 = g0 * cos_phase + knot_slope(phase_keys[b], knot0) * sin_phase;
      g1 = g1 * cos_phase + knot_slope(phase_keys[b], knot1) * sin_phase;
    }
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

}  // namespace turning_bands_detail

// One evaluation: band coordinates, profiles, and the sums into values and gradients, on vectors.
// (With Eigen's products around a vector band loop, the products took as long as the loop.) Built
// three times, for AVX-512, AVX2 and the baseline; the files that build it are compiled without fused
// multiply-adds (CMakeLists.txt), so the builds give the same bits.
template <int N>
struct TurningBandsNoise<N>::Kernel {
  template <int W, bool kPeriodic, bool kPhase>
  [[gnu::always_inline]] static inline void run(const TurningBandsNoise& noise, const Vec<N>& x,
                                                NoiseSample<N, N - 1>& out) {
    using turning_bands_detail::load_lanes;
    static_assert(kLanes % W == 0);
    // W doubles in one vector register: 8 with AVX-512, 4 with AVX2, 2 with SSE2 (the baseline). Every lane sees
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
    turning_bands_detail::band_profiles<kUsedBands, kPeriodic, kPhase>(t, noise.keys_.data(), noise.knot_masks_.data(),
                                                                        value, slope, noise.phase_keys_.data(),
                                                                        noise.cos_phase_, noise.sin_phase_);
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

  template <bool kPeriodic, bool kPhase>
  static void baseline(const TurningBandsNoise& noise, const Vec<N>& x, NoiseSample<N, N - 1>& out) {
    run<2, kPeriodic, kPhase>(noise, x, out);
  }

#if defined(__x86_64__)
  template <bool kPeriodic, bool kPhase>
  [[gnu::target("avx512f,avx512dq,avx512vl")]] static void avx512(const TurningBandsNoise& noise, const Vec<N>& x,
                                                                  NoiseSample<N, N - 1>& out) {
    run<8, kPeriodic, kPhase>(noise, x, out);
  }

  // AVX2 without FMA: 4 doubles per vector for the band coordinates and the gradient sums (the
  // hashes' 64-bit multiplies stay scalar); 1.2x the baseline in 3D and 7D (bench/results.md).
  template <bool kPeriodic, bool kPhase>
  [[gnu::target("avx2")]] static void avx2(const TurningBandsNoise& noise, const Vec<N>& x, NoiseSample<N, N - 1>& out) {
    run<4, kPeriodic, kPhase>(noise, x, out);
  }
#endif

  // The widest build the CPU runs that `simd` allows (Simd in core/simd.hpp), else the baseline.
  template <bool kPeriodic, bool kPhase>
  static auto choose_build(Simd simd) -> decltype(&baseline<kPeriodic, kPhase>) {
#if defined(__x86_64__)
    if (simd == Simd::best && cpu_has_avx512()) return &avx512<kPeriodic, kPhase>;
    if (simd != Simd::baseline && cpu_has_avx2()) return &avx2<kPeriodic, kPhase>;
#endif
    (void)simd;
    return &baseline<kPeriodic, kPhase>;
  }
  // Phase 0 takes the phase-free build: the bits of the noise before phases existed.
  template <bool kPeriodic>
  static auto choose(Simd simd, bool rotating) -> decltype(&baseline<kPeriodic, false>) {
    return rotating ? choose_build<kPeriodic, true>(simd) : choose_build<kPeriodic, false>(simd);
  }
};

}  // namespace dfvn
