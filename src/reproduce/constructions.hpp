// `dfvn-sample reproduce constructions` (issue 26, item 4): the older divergence-free constructions beside
// DFVN, in 2D and 3D, on the same noise bases and frequency. Curl noise (Bridson, Hourihan and Nordenstam
// 2007: c = curl psi, FieldKind::curl), bitangent noise (seed 004: the cross product of two simplex
// gradients, which is the 3D DFVN field on the simplex bases: `simplex` its one-traversal optimised form,
// `simplex-separate` its reference form) and DFVN on every other basis. Per field: divergence on uniform
// random points (field/diagnose.hpp), ns per evaluation, the |c| distribution, the end-point RMSE of
// Euler and RK4 with 64 and 512 steps against 2048 RK4 steps (as Table 2), with and without reprojection
// where it exists (curl noise has none), and the escape fraction from the cube and into a sphere
// obstacle (bounded fields, Bridson's ramp); then Bridson's Figure 1, streamlines of 2D curl noise
// around a disc obstacle.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "dfvn/core/progress.hpp"
#include "dfvn/field/dfvn_field.hpp"
#include "dfvn/integrate/trace.hpp"

namespace dfvn {

struct ConstructionsConfig {
  double frequency = 2.0;            // cycles per unit length, every field
  double trace_time = 0.5;           // t of every trace (RMS |c| = 1: about one cycle at the default frequency)
  std::uint64_t divergence_points = 100000;  // uniform random points of the divergence (issue 26's target count)
  std::uint64_t speed_points = 20000;        // points of the timing and |c| pass (single thread)
  std::uint64_t trace_starts = 128;          // starts of the accuracy traces, uniform in [0,1]^N, free field
  std::uint64_t escape_starts = 1000;        // starts of the escape traces, uniform in the bounded domain
  std::uint64_t seed = 1;
  int threads = 0;
  std::string out_dir = "out/constructions";
  // The bounded fields of the escape counts: the cube [0,1]^N, Bridson's ramp of this width (length
  // units) on the cube's faces and on one sphere obstacle at the centre.
  static constexpr double kBoundaryWidth = 0.05;
  static constexpr double kObstacleRadius = 0.15;
  // Escapes are counted for the 64-step variants only: with 512 steps they are rare (0 to 1% in 3D, 0 to
  // 0.2% in 2D in a first run with 500 starts), and those traces would cost 8 times as much.
  static constexpr int kEscapeSteps = 64;
  // Figure 1: streamlines of 2D curl noise around the disc obstacle.
  static constexpr int kFigureSeedsPerAxis = 14;
  static constexpr double kFigureLength = 0.35;  // time traced forward and backward from each seed
  static constexpr int kFigureSteps = 300;       // RK4 steps of each half

  void validate() const;  // throws std::invalid_argument naming the option
};

// The three constructions. bitangent is the cross-product (DFVN) field on simplex or simplex-separate in
// 3D; in 2D the cross product of one gradient is the 2D DFVN field, so those rows are dfvn.
enum class Construction { curl, bitangent, dfvn };
std::string_view to_string(Construction construction);

struct ConstructionVariant {
  Integrator integrator = Integrator::rk4;
  int steps = 64;
  Reprojection reprojection = Reprojection::none;  // gauss_newton (the tracer's default, up to 10 updates) or none
};

struct ConstructionTraceRow {
  ConstructionVariant variant;
  double endpoint_rmse = 0.0;       // sqrt(mean |x_end - x_ref|^2) over the trace starts
  double evaluations_per_trace = 0.0;
  // Fractions of the escape starts whose end is outside the cube / inside the obstacle; NaN (not measured)
  // unless steps == kEscapeSteps.
  double escape_cube = std::numeric_limits<double>::quiet_NaN();
  double escape_obstacle = std::numeric_limits<double>::quiet_NaN();
};

struct ConstructionField {
  int dimension = 2;
  Construction construction = Construction::dfvn;
  FieldKind kind = FieldKind::dfvn;
  NoiseBasis noise = NoiseBasis::turning_bands;
  // Divergence (diagnose_field): |div c| / |Dc| over the divergence points.
  double divergence_median = 0.0, divergence_p95 = 0.0, divergence_max = 0.0;
  std::uint64_t still_points = 0;
  // Timing and |c| over the speed points (one thread, wall clock: varies between runs).
  double ns_per_evaluation = 0.0;
  double speed_rms = 0.0, speed_q01 = 0.0, speed_q10 = 0.0, speed_q50 = 0.0, speed_q90 = 0.0, speed_q99 = 0.0;
  double fraction_below_1pct = 0.0;  // of the RMS
  std::vector<ConstructionTraceRow> traces;  // curl: no reprojection rows (none exists)
};

struct ConstructionsResult {
  ConstructionsConfig config;
  std::vector<ConstructionField> fields;
  // Figure 1's streamlines: x, y per point, one polyline per entry (backward half reversed, then forward).
  std::vector<std::vector<std::array<double, 2>>> streamlines;
  int threads = 1;
  std::string machine;
  double seconds = 0.0;
};

// The tracing variants of a construction: Euler and RK4, 64 and 512 steps, without reprojection and (for
// the cross-product fields) with Gauss-Newton reprojection.
std::vector<ConstructionVariant> construction_variants(FieldKind kind);
// The fields in the order they are measured: 2D then 3D, curl then the cross product, every basis.
std::vector<ConstructionField> construction_fields();

// `progress`: per field its divergence, speed, accuracy and escape stages, then the figure;
// constructions_stage_weights gives their expected costs in that order.
ConstructionsResult run_constructions(const ConstructionsConfig& config, const StageProgress& progress = {});
std::vector<double> constructions_stage_weights(const ConstructionsConfig& config);

// The claim: the cross-product field with reprojection has a lower end-point RMSE than curl noise
// on the same basis at equal integrator and steps. One cell per (dimension, basis, integrator, steps).
struct ClaimCell {
  int dimension = 2;
  NoiseBasis noise = NoiseBasis::turning_bands;
  Integrator integrator = Integrator::rk4;
  int steps = 64;
  double reprojected = 0.0, curl = 0.0;
  bool holds() const { return reprojected < curl; }
};
std::vector<ClaimCell> constructions_claim(const ConstructionsResult& result);

// DIR/constructions.csv, DIR/constructions.md, DIR/curl_obstacle.csv (Figure 1's streamlines) and, with
// gnuplot, DIR/curl_obstacle.png. Returns the Markdown; throws PlotError when gnuplot fails.
std::string write_constructions(const ConstructionsResult& result, const std::function<void(const std::string&)>& log);
std::vector<std::string> constructions_output_files();
std::string constructions_csv(const ConstructionsResult& result);
std::string constructions_markdown(const ConstructionsResult& result);

}  // namespace dfvn
