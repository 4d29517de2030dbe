// Image warping's traces a vector of pixels at a time (private to warp/): the 2D DFVN field of quintic
// gradient noise (the shader's field, Table 2) evaluated for 4 or 8 start points at once, Euler or RK4
// steps with or without Newton reprojection, the same operations in the same order as Tracer<2> over
// DfvnField<2> (integrate/trace_impl.hpp, field/dfvn_field.cpp, noise/gradient_noise.cpp, the 2D case of
// field/cross_product.hpp), so every end point is the same bits as Tracer<2>::trace's, and so is the
// count of field evaluations. Lanes whose trace would read the noise outside its domain are left to
// Tracer<2> (`traced` false).
//
// Built three times like core/simd.hpp's kernels (warp_lanes.cpp: the x86-64 baseline with two lanes
// (SSE2), AVX2 with four, AVX-512 with eight), picked at run time; no fused multiply-adds
// (CMakeLists.txt), so every build gives the same bits.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "dfvn/core/simd.hpp"
#include "dfvn/field/dfvn_field.hpp"
#include "dfvn/integrate/trace.hpp"

namespace dfvn::warp_lanes {

// The field: f(x) = (A / s) n(s x) and grad f = A grad n(s x), n(y) quintic gradient noise at
// y' = R y + o with hash key `key` (noise/gradient_noise.hpp), its domain |F x_j| < 2^50.
struct QuinticField2d {
  double scale = 1.0, amplitude = 1.0, frequency = 1.0;
  double rotation[2][2] = {{1.0, 0.0}, {0.0, 1.0}};
  double offset[2] = {0.0, 0.0};
  std::uint64_t key = 0, multiplier[2] = {0, 0};
};

// The field's parameters when it is plain 2D quintic gradient noise at phase 0 (DfvnField::plain_basis),
// and the tracer's when its reprojection is none or Newton; nullopt otherwise (then use Tracer<2>).
std::optional<QuinticField2d> quintic_field_2d(const DfvnField<2>& field, const TraceOptions& options);

// Traces the `count` points (x[i], y[i]) for `time` with `options` (steps, integrator, Newton iterations,
// tolerance, condition, update ratio): end[i] = (end_x[i], end_y[i]) and evaluations[i] the field
// evaluations, both as Tracer<2>::trace gives them, where traced[i] is true; where it is false the
// trace reached the edge of the noise domain and the slots hold nothing meaningful.
void trace(const QuinticField2d& field, const TraceOptions& options, double time, std::size_t count, const double* x,
           const double* y, double* end_x, double* end_y, std::int64_t* evaluations, std::uint8_t* traced,
           Simd simd = Simd::best);

}  // namespace dfvn::warp_lanes
