// One-command reproductions of the paper's Table 1 (with Figure 4) and Table 2 (with Figure 5).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "dfvn/experiment/experiment.hpp"
#include "dfvn/experiment/realizations.hpp"
#include "dfvn/warp/image_warp.hpp"

namespace dfvn {

using Log = std::function<void(const std::string&)>;

// ---- Table 1: point sets in 3D-7D (Section 5.1) ----

struct Table1Config {
  std::vector<int> dimensions = {3, 4, 5, 6, 7};
  std::uint64_t seed = 1;
  // Realizations R: seeds seed..seed+R-1, every cell reported as mean and standard deviation (the 7D
  // NN minimum varies by +-30% between seeds). One realization of 3D-7D took 97 s on a shared 2-core
  // Xeon (7D 76 s of it, its Poisson disk set 48 s), so 3 keeps the table near 5 minutes, like Table 2.
  int realizations = 3;
  int threads = 0;
  CnjOptions cnj;         // our documented defaults (the paper's step and frequency are unpublished)
  RdfOptions rdf;
  std::string out_dir = "table1";

  void validate() const;  // throws std::invalid_argument naming the option
};

// Table 1's K: 10 for 3D-5D, 7 for 6D, 6 for 7D (Section 5.1). Throws for dimensions outside 3..7.
int table1_grid(int dimension);

// "3-7", "3,5,7" or "4" -> dimensions in 3..7; throws std::invalid_argument otherwise.
std::vector<int> parse_dimension_list(std::string_view text);

// One cell of Table 1 over the realizations.
struct Table1Cell {
  MeanSd nn_median, nn_min, seconds, points;  // seconds: generation plus statistics
  double smallest_min = 0.0;                  // the smallest NN minimum of any realization
};

struct Table1Result {
  std::vector<SampleConfig> configs;  // one per dimension, with the first realization's seed
  int realizations = 1;
  // runs[d][r]: dimension d, realization r (seed + r), one result per method (cnj, jitter, pds, sobol).
  // Only the first realization carries the RDFs (rdf.csv, Figure 4).
  std::vector<std::vector<std::vector<MethodResult>>> runs;
  // simplex_cnj[d][r]: CNJ with the paper's construction (simplex noise), beside ours (the default basis).
  std::vector<std::vector<MethodResult>> simplex_cnj;
  std::vector<double> wall_seconds;  // per dimension, every realization and column together
  std::string machine;               // where the times were measured (core/machine.hpp)

  // The first realization's results of dimension index d (with the RDFs).
  const std::vector<MethodResult>& first(std::size_t d) const { return runs[d].front(); }
  // Mean and sd over the realizations of one method; the simplex column with `simplex`. Throws
  // std::out_of_range if the method was not run.
  Table1Cell cell(std::size_t d, Method method, bool simplex = false) const;
};

// `progress`: per dimension and realization, each method's stages (run_sampling's), then the simplex
// column's; table1_stage_weights gives their expected costs in that order.
Table1Result run_table1(const Table1Config& config, const StageProgress& progress = {});
std::vector<double> table1_stage_weights(const Table1Config& config);

// DIR/table1.csv (one row per realization, column and dimension), DIR/table1_summary.csv (their mean,
// sd and standard error, experiment/realizations.hpp), DIR/rdf.csv
// (the first realization), DIR/table1.md; then DIR/figure4.png (scripts/figure4.gp) when gnuplot is
// installed (otherwise `log` says how to get it). Returns the Markdown; throws PlotError when gnuplot
// fails.
std::string write_table1(const Table1Config& config, const Table1Result& result, const Log& log);
// The files write_table1 writes into config.out_dir (figure4.png only with gnuplot), for the check of
// a run's outputs before it starts (io/atomic_file.hpp, check_outputs).
std::vector<std::string> table1_output_files();
std::string table1_markdown(const Table1Result& result);

// ---- Table 2: image warping (Section 5.2) ----

struct Table2Config {
  WarpSetting setting = WarpSetting::shader;
  WarpConfig warp = shader_warp_config();  // the main resolution (images, figure, RMSE)
  // A second resolution, width in pixels with the same aspect ratio, at which every RMSE is measured
  // again to show how far it has converged with resolution (the paper measured at 3840x2160). 0: none.
  int second_width = 192;
  // Figure 5's top row: the warp at these times, each with 1000 RK4 steps (as the paper's).
  std::vector<double> figure_times = {0.05, 0.2, 0.5};
  static constexpr int kFigureSteps = 1000;

  void validate() const;  // throws std::invalid_argument naming the option
};

struct Table2Row {
  WarpVariant variant;
  double rmse = 0.0;         // against the reference at the main resolution, 8-bit units, from float values
  double rmse_second = 0.0;  // the same at the second resolution (0 if none)
  double rmse_wraparound = 0.0;  // main resolution, 8-bit images, wrap-around arithmetic (rmse_8bit_wraparound)
  double seconds = 0.0;      // wall time of the warp at the main resolution
  double megapixels_per_second = 0.0;
  std::int64_t field_evaluations = 0;  // deterministic measure of the work
};

struct Table2Result {
  Table2Config config;
  WarpConfig second{.width = 0, .height = 0};  // the second resolution's configuration (width 0 if none)
  double reference_seconds = 0.0;
  int threads = 1;
  std::string machine;  // where the times were measured (core/machine.hpp)
  std::vector<Table2Row> rows;
  std::vector<FloatImage> images;    // per row, at the main resolution
  FloatImage source, reference;
  std::vector<FloatImage> timeline;  // per figure time
};

// Euler and RK4, 64 and 512 steps, 0, 1 and 10 Newton reprojection steps (Eq. 12), t = 0.5; the
// reference is 2048 RK4 steps without reprojection (as the paper's). Then the second resolution and
// Figure 5's top row.
// `progress`: one stage per image warped, in the order of table2_stage_weights, which gives each
// stage's expected cost (pixels x expected field evaluations per pixel).
Table2Result run_table2(const Table2Config& config, const StageProgress& progress = {});
std::vector<double> table2_stage_weights(const Table2Config& config);

// DIR/table2.csv, DIR/table2.md, DIR/<variant>.png, DIR/source.png, DIR/reference.png,
// DIR/timeline.csv with DIR/time-<t>.png, and, with gnuplot, DIR/figure5.png
// (scripts/figure5.gp). Returns the Markdown; throws PlotError when gnuplot fails.
std::string write_table2(const std::string& out_dir, const Table2Result& result, const Log& log);
// The files write_table2 writes into its directory for this configuration (figure5.png only with gnuplot).
std::vector<std::string> table2_output_files(const Table2Config& config);
std::string table2_markdown(const Table2Result& result);

// The paper's qualitative claims about Table 2, each a strict inequality on our float RMSE.
struct Table2Conclusions {
  bool rk4_512_differs_from_reference = false;  // RMSE(rk4, 512, no reprojection) > 0
  bool rk4_beats_euler = false;                 // lower RMSE at equal steps and reprojection, all 6 rows
  bool more_steps_lower_rmse = false;           // 512 steps below 64 for both integrators and reprojections
  bool reprojection_lowers_rmse = false;        // 1 Newton step below none, both integrators, 64 and 512 steps
  bool rk4_64_reproject_beats_euler_512 = false;  // in RMSE and in measured time
  bool rk4_64_reproject_does_less_work = false;   // fewer field evaluations than 512 Euler steps
};
// At the main resolution, or with `second` at the second one.
Table2Conclusions table2_conclusions(const Table2Result& result, bool second = false);

}  // namespace dfvn
