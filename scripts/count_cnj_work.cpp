// The work of one CNJ point in 7D (one RK4 step + Gauss-Newton reprojection on the 6^7 paper lattice: the
// main job's step count, traced in the free field; drop mode's default of two steps costs about twice; or,
// with a third argument, the library's CNJ on the torus or in the cube, conformant):
// traces the first `points` lattice points on one thread and prints the field evaluations and
// reprojection updates per point, and the arithmetic floor those need. scripts/count_cnj_work.sh runs
// it under callgrind at two sizes; the difference in instructions / difference in points is the
// measured cost per point, to set against the floor.
//
// Floor, in arithmetic operations (floating-point operations plus the integer multiplies, adds,
// shifts and xors of the hashes), counted from the algorithm.
// Turning bands (the default basis), B = 2N(N-1) bands: per band the coordinate w.x + o 2N, floor 3,
//   offset in the cell 2, two knot slopes (odd multiply and add, mix64's 3 shifts, 3 xors and 2
//   multiplies, conversion and scaling: 12 each, plus the next knot 1) 25, fade 7, fade slope 4, value
//   7, slope 9; per function the value sum K and the gradient W_i^T p' 2NK plus N for the 1/sqrt(K).
// Simplex, with every one of the N+1 vertices inside the kernel (an upper floor: vertices outside the
//   kernel cost only their offset and distance): skew and floor 4N; per vertex: offset update 2N,
//   |d|^2 2N, kernel powers 4, hash N multiplies + N adds + mix64 (4); per vertex and function: g.d N-1,
//   value 2, gradient 3N+1.
//   field: scaling 2N(N-1); cross product: LU of N x (N-1), sum_k 2(N-1-k)(N-k) + N pivot divisions,
//     back substitution (N-1)N, output N.
//   RK4 combination 10N per step; Gauss-Newton update: Householder QR of N x (N-1), about
//     2(N-1)^2 (N - (N-1)/3), R^T solve (N-1)^2, Q application 4N(N-1), residual N-1, step N.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "dfvn/integrate/trace.hpp"
#include "dfvn/sampling/curl_noise_jitter.hpp"
#include "dfvn/sampling/lattice.hpp"

namespace {

constexpr int N = 7;

double floor_per_evaluation(dfvn::NoiseBasis basis) {
  double lu = N;
  for (int k = 0; k < N - 1; ++k) lu += 2.0 * (N - 1 - k) * (N - k);
  const double cross = lu + (N - 1) * N + N;
  const double field = N + 2 * N * (N - 1) + cross;  // s x, scaling of values and gradients, cross product
  if (basis == dfvn::NoiseBasis::turning_bands) {
    const double bands = 2.0 * N * (N - 1), per_band = 2 * N + 3 + 2 + 25 + 7 + 4 + 7 + 9;
    const double per_function = 2.0 * N + 2.0 * N * (2 * N) + N;
    return bands * per_band + (N - 1) * per_function + field;
  }
  const double per_vertex = 2 * N + 2 * N + 4 + (2 * N + 4);
  const double per_function = (N - 1) + 2 + (3 * N + 1);
  return 4 * N + (N + 1) * (per_vertex + (N - 1) * per_function) + field;
}

double floor_per_update() {
  const double m = N - 1;
  return 2 * m * m * (N - m / 3) + m * m + 4 * N * m + m + N;
}

}  // namespace

int main(int argc, char** argv) {
  const long points = argc > 1 ? std::atol(argv[1]) : 10000;
  dfvn::CnjOptions options;
  if (argc > 2) options.noise = dfvn::parse_noise_basis(argv[2]);
  const std::string mode = argc > 3 ? argv[3] : "free";
  const dfvn::LatticeSpec lattice{N, 6, dfvn::Protocol::paper};
  if (points < 1 || points > static_cast<long>(lattice.point_count()) || (mode != "free" && mode != "torus" && mode != "cube")) {
    std::fprintf(stderr, "usage: count_cnj_work [points in 1..%llu] [noise basis] [free|torus|cube]\n",
                 static_cast<unsigned long long>(lattice.point_count()));
    return 2;
  }
  dfvn::TraceStats stats;
  double checksum = 0.0;
  std::uint64_t retraced = 0;
  if (mode == "free") {
    const double time = options.step_scale * dfvn::average_neighbour_distance(N) * lattice.spacing();
    const dfvn::DfvnField<N> field(1, dfvn::FieldOptions{options.noise, options.frequency / lattice.spacing()});
    const dfvn::Tracer<N> tracer(field, dfvn::cnj_trace_options(options));
    for (long i = 0; i < points; ++i) {
      dfvn::Vec<N> x0;
      lattice.point(static_cast<std::uint64_t>(i), x0.data());
      checksum += tracer.trace(x0, time, &stats).sum();
    }
  } else {
    // The library's own CNJ of the first `points` lattice rows, on one thread: on the torus (the main job's
    // default: the periodic basis, the free field's steps) or in the cube, conformant (the bounded field,
    // one step, traces that end outside retraced with more steps).
    options.domain = mode == "torus" ? dfvn::DomainKind::torus : dfvn::DomainKind::cube;
    options.domain_mode = dfvn::DomainMode::conformant;
    const dfvn::CnjResult r = dfvn::curl_noise_jitter_range(lattice, options, 1, 0, static_cast<std::uint64_t>(points), 1);
    stats = r.trace_stats;
    retraced = r.retraced;
    for (double c : r.points.coordinates) checksum += c;
  }
  const auto per_point = [&](std::int64_t count) { return static_cast<double>(count) / static_cast<double>(points); };
  const double evaluations = per_point(stats.field_evaluations);
  const double updates = per_point(stats.reprojection_updates + stats.skipped_updates);
  // The floor counts the free field's arithmetic for the evaluations and updates made: what the bounded
  // field's wall factor and the torus' knot masks add per evaluation shows in the ratio, not in the floor.
  const double floor = evaluations * floor_per_evaluation(options.noise) + updates * floor_per_update() + 10 * N;
  std::printf("mode %s\npoints %ld\nfield_evaluations_per_point %.4f\nreprojection_updates_per_point %.4f\n"
              "retraced_fraction %.4f\nfloor_ops_per_evaluation %.0f\nfloor_ops_per_update %.0f\nfloor_ops_per_point %.0f\n"
              "checksum %.17g\n",
              mode.c_str(), points, evaluations, updates, static_cast<double>(retraced) / static_cast<double>(points),
              floor_per_evaluation(options.noise), floor_per_update(), floor, checksum);
  return 0;
}
