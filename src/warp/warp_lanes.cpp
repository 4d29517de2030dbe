#include "dfvn/warp/warp_lanes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "dfvn/noise/gradient_noise.hpp"

namespace dfvn::warp_lanes {

std::optional<QuinticField2d> quintic_field_2d(const DfvnField<2>& field, const TraceOptions& options) {
  const auto* basis = dynamic_cast<const QuinticGradientNoise<2>*>(field.plain_basis());
  if (!basis || basis->phase() != 0.0) return std::nullopt;
  if (options.reprojection == Reprojection::gauss_newton) return std::nullopt;
  QuinticField2d f;
  f.scale = field.scale();
  f.amplitude = field.amplitude();
  f.frequency = field.options().frequency;  // DfvnField::in_domain's
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 2; ++c) f.rotation[r][c] = basis->rotation(0)(r, c);
    f.offset[r] = basis->offset(0)[r];
    f.multiplier[r] = QuinticGradientNoise<2>::lattice_multiplier(r);
  }
  f.key = basis->key(0);
  return f;
}

// The three builds of the kernel (warp_lanes_kernel.inc), each in its own namespace.
namespace baseline {
inline constexpr int kLanes = 2;  // SSE2's pairs
typedef double D __attribute__((vector_size(kLanes * sizeof(double))));
typedef std::int64_t I __attribute__((vector_size(kLanes * sizeof(double))));
typedef std::uint64_t U __attribute__((vector_size(kLanes * sizeof(double))));
inline D sqrt_lanes(D v) {
#if defined(__x86_64__)
  return D(_mm_sqrt_pd(__m128d(v)));
#else
  for (int i = 0; i < kLanes; ++i) v[i] = std::sqrt(v[i]);
  return v;
#endif
}
#include "dfvn/warp/warp_lanes_kernel.inc"
}  // namespace baseline

#if defined(__x86_64__)
#pragma GCC push_options
#pragma GCC target("avx2")
namespace avx2 {
inline constexpr int kLanes = 4;
typedef double D __attribute__((vector_size(kLanes * sizeof(double))));
typedef std::int64_t I __attribute__((vector_size(kLanes * sizeof(double))));
typedef std::uint64_t U __attribute__((vector_size(kLanes * sizeof(double))));
inline D sqrt_lanes(D v) { return D(_mm256_sqrt_pd(__m256d(v))); }
#include "dfvn/warp/warp_lanes_kernel.inc"
}  // namespace avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f,avx512dq,avx512vl")
namespace avx512 {
inline constexpr int kLanes = 8;
typedef double D __attribute__((vector_size(kLanes * sizeof(double))));
typedef std::int64_t I __attribute__((vector_size(kLanes * sizeof(double))));
typedef std::uint64_t U __attribute__((vector_size(kLanes * sizeof(double))));
// The masked form: the plain one leaves GCC 12 warning about its undefined source operand.
inline D sqrt_lanes(D v) { return D(_mm512_mask_sqrt_pd(__m512d(v), 0xFF, __m512d(v))); }
#include "dfvn/warp/warp_lanes_kernel.inc"
}  // namespace avx512
#pragma GCC pop_options
#endif

void trace(const QuinticField2d& field, const TraceOptions& options, double time, std::size_t count, const double* x,
           const double* y, double* end_x, double* end_y, std::int64_t* evaluations, std::uint8_t* traced, Simd simd) {
  if (count == 0) return;
  const bool rk4 = options.integrator == Integrator::rk4, newton = options.reprojection == Reprojection::newton;
  const auto settings = [&]<class S>(S) {
    return S{options.steps, time / options.steps, options.reproject_iterations, options.residual_tolerance,
             1.0 / (options.max_condition * options.max_condition), options.max_update_ratio};
  };
#if defined(__x86_64__)
  if (simd == Simd::best && cpu_has_avx512())
    return avx512::trace_points(field, settings(avx512::Settings{}), rk4, newton, count, x, y, end_x, end_y, evaluations, traced);
  if (simd == Simd::best && cpu_has_avx2())
    return avx2::trace_points(field, settings(avx2::Settings{}), rk4, newton, count, x, y, end_x, end_y, evaluations, traced);
#endif
  baseline::trace_points(field, settings(baseline::Settings{}), rk4, newton, count, x, y, end_x, end_y, evaluations, traced);
}

}  // namespace dfvn::warp_lanes
