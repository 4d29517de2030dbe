// The CNJ study: curl noise jittering (each noise basis) against random jitter over a grid of noise
// frequencies, step scales and integration step counts, compared at equal RMS displacement, equal
// neighbour disorder and equal lattice order. It chooses the CNJ defaults (CnjOptions) by a stated rule.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dfvn/noise/noise_functions.hpp"
#include "dfvn/reproduce/reproduce.hpp"
#include "dfvn/sampling/curl_noise_jitter.hpp"

namespace dfvn {

// Which lattice the study jitters.
//  interior: the study's own cell-centred K^N lattice (cnj_study_grid), statistics over its interior
//            sites, so nothing is dropped and no boundary effect enters.
//  paper:    the lattice of the paper's Table 1 (linspace(0.05, 0.95, K), K = table1_grid), points that
//            leave [0,1]^N dropped as the paper does, for CNJ and for the matched jitter alike, and
//            statistics over every point kept.
enum class StudyLattice { interior, paper };
std::string_view to_string(StudyLattice lattice);
StudyLattice parse_study_lattice(std::string_view name);  // throws std::invalid_argument

struct CnjStudyConfig {
  StudyLattice lattice = StudyLattice::interior;
  std::vector<int> dimensions = {3, 4, 5, 6, 7};
  std::uint64_t seed = 1;  // seeds seed .. seed + seeds - 1
  int seeds = 3;  // --realizations
  std::vector<NoiseBasis> bases = {NoiseBasis::simplex, NoiseBasis::turning_bands};
  std::vector<double> frequencies = {0.1, 0.2, 0.35, 0.5, 1.0};  // cycles per lattice spacing
  std::vector<double> step_scales = {0.2, 0.35, 0.5};           // t = C dbar(N) spacing
  // Integration steps M per trace (Algorithm 1, each step RK4 + reprojection): Section 5.1's one, and
  // the free field's default (kFreeFieldSteps).
  std::vector<int> steps = {1, kFreeFieldSteps};
  int threads = 0;
  std::string out_dir = "out/cnj-study";

  void validate() const;  // throws std::invalid_argument naming the option
};

// The lattice of the study: K^N cell centres of [0,1]^N (spacing 1/K), with K = 12, 8, 6, 5, 5 for
// 3D..7D (2D: 24, 8D: 4) so that every run stays below ~80,000 points; statistics over the interior
// sites (at least one spacing from the lattice's outer layer), whose neighbours are all present, so no
// point is dropped and no boundary effect enters.
int cnj_study_grid(int dimension);
// K for a lattice and dimension: cnj_study_grid or table1_grid.
int study_grid(StudyLattice lattice, int dimension);

// Nearest-neighbour packing over the interior points, in lattice spacings.
struct Packing {
  double nn_min = 0.0;
  double nn_q01 = 0.0;
};

// One CNJ run and the three jitter runs matched to it (same lattice and seed).
struct CnjStudyRow {
  int dimension = 0;
  int grid = 0;
  NoiseBasis basis{};
  double frequency = 0.0;
  double step_scale = 0.0;
  int steps = 1;
  std::uint64_t seed = 0;
  // CNJ, displacements in spacings, over every lattice point.
  double rms_displacement = 0.0;
  double median_over_rms = 0.0;
  double fraction_unmoved = 0.0;
  double neighbour_disorder = 0.0;
  double lattice_order = 0.0;
  double skipped_update_fraction = 0.0;  // Gauss-Newton updates not taken, per point
  Packing cnj;
  double dropped_fraction = 0.0;  // CNJ points that left [0,1]^N (paper lattice only)
  // Uniform jitter of half-width h (spacings) chosen to match CNJ's RMS displacement
  // (h = rms sqrt(3/N)), neighbour disorder (h = disorder / sqrt(2N/3)) and lattice order
  // ((sin 2 pi h / 2 pi h)^2 = order, 0 < h <= 1/2).
  double h_rms = 0.0, h_disorder = 0.0, h_order = 0.0;
  Packing jitter_rms, jitter_disorder, jitter_order;
};

// The jitter reference curve of the figure: uniform jitter at half-widths 0.05 .. 0.7 spacings.
struct JitterCurvePoint {
  int dimension = 0;
  double half_width = 0.0;
  double rms_displacement = 0.0, neighbour_disorder = 0.0, lattice_order = 0.0;
  Packing packing;
};

struct CnjStudyResult {
  CnjStudyConfig config;
  std::vector<CnjStudyRow> rows;
  std::vector<JitterCurvePoint> jitter_curve;
  double seconds = 0.0;
};

// `progress`: one stage per cell and seed ("4D simplex F=0.35 C=0.5 M=2 seed 1"), then each dimension's
// jitter curve; cnj_study_stage_weights gives their expected costs in that order.
CnjStudyResult run_cnj_study(const CnjStudyConfig& config, const StageProgress& progress = {});
std::vector<double> cnj_study_stage_weights(const CnjStudyConfig& config);

// The rule that picks the CNJ defaults, applied to the default basis (kDefaultNoiseBasis), on means
// over seeds: among the (frequency, step scale, steps) cells that in EVERY studied dimension move points
// (frac_unmoved <= 1%, median/RMS displacement >= 0.5) and beat jitter at equal RMS displacement in
// both nn_q01 and nn_min, take the one with the largest geometric mean over dimensions of
// nn_q01(CNJ) / nn_q01(jitter at equal neighbour disorder): the comparison that does not reward moving
// neighbours together (a translation scores zero disorder). nullopt when no cell qualifies.
struct CnjDefaultsChoice {
  double frequency = 0.0;
  double step_scale = 0.0;
  int steps = 1;
  double score = 0.0;  // the geometric mean above
};
std::optional<CnjDefaultsChoice> choose_cnj_defaults(const CnjStudyResult& result);

// DIR/cnj_study.csv (one row per run), DIR/cnj_study_jitter.csv (the reference curve), DIR/cnj_study.md
// (the reading) and, with gnuplot, DIR/cnj_study.png (scripts/cnj_study.gp). Returns the Markdown;
// throws PlotError when gnuplot fails.
std::string write_cnj_study(const CnjStudyResult& result, const Log& log);
// The files write_cnj_study writes into config.out_dir (cnj_study.png only with gnuplot).
std::vector<std::string> cnj_study_output_files();
std::string cnj_study_markdown(const CnjStudyResult& result);

}  // namespace dfvn
