// Curl noise jittering on the unit sphere S^{N-1} (Section 4, "DFVN on (hyper)surfaces"): f_1 = |x|^2
// (scaled, field/constraint.hpp) makes c tangent to every sphere |x| = r, so traces along it, with
// Algorithm 1's reprojection holding f_1 at its start value, stay on the sphere.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "dfvn/sampling/curl_noise_jitter.hpp"
#include "dfvn/core/point_set.hpp"

namespace dfvn {

// The start set: the cell-centred K^N lattice on [-1, 1]^N (spacing h = 2/K), its points in the shell
// 1 - h/2 <= |x| < 1 + h/2, projected radially. The shell holds one lattice layer around the sphere
// in every direction, so the projected points cover it evenly, about area(S^{N-1}) / h^(N-1) of them
// (|x| = 1 to rounding). Points: count x N, row-major; domain [-1, 1]^N.
PointSet sphere_start_set(int dimension, int grid);
double sphere_start_spacing(int grid);  // h = 2 / K

struct SphereCnjResult {
  PointSet points;                  // on the unit sphere: |x| = 1 within 1e-12, every start point
  std::uint64_t retraced = 0;       // traces that ended off the sphere and were traced again with more steps
  std::uint64_t kept_at_site = 0;   // retraced points that no refinement kept on it (stay at their start)
  double trace_time = 0.0;          // step_scale * dbar(N - 1) * h: the surface is (N-1)-dimensional
  double field_frequency = 0.0;     // frequency / h
  double rms_displacement = 0.0;
  TraceStats trace_stats;
};

// The options the sphere traces with: `options` in conformant mode. Every trace is bound to the sphere
// and refined when it ends off it, as in a conformant domain, so it takes the conformant step count
// whatever the domain mode says.
CnjOptions sphere_cnj_options(const CnjOptions& options);

// Every start point traced along the field with f_1 = |x|^2 and the N-2 other functions noise, with
// sphere_cnj_options(options); their domain settings are not used. Throws std::invalid_argument for N < 3.
SphereCnjResult sphere_curl_noise_jitter(int dimension, int grid, const CnjOptions& options, std::uint64_t seed,
                                         int threads, const FractionProgress& progress = {});

// `count` points uniform on S^{N-1} (normalised Gaussian vectors, Box-Muller from the counter-based
// generator): the random reference.
PointSet uniform_points_on_sphere(int dimension, std::uint64_t count, std::uint64_t seed, int threads);

}  // namespace dfvn
