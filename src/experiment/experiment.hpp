// The sampling experiment of Section 5.1: generate the configured point sets and measure them.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dfvn/core/progress.hpp"
#include "dfvn/sampling/curl_noise_jitter.hpp"
#include "dfvn/sampling/lattice.hpp"
#include "dfvn/core/point_set.hpp"
#include "dfvn/sampling/sobol.hpp"
#include "dfvn/sampling/sphere_jitter.hpp"
#include "dfvn/stats/lattice_displacement.hpp"
#include "dfvn/stats/nearest_neighbour.hpp"
#include "dfvn/stats/radial_distribution.hpp"

namespace dfvn {

struct SampleConfig {
  int dimension = 7;
  int grid = 6;
  std::uint64_t seed = 1;
  int threads = 0;
  // The main job's: CNJ, jitter at CNJ's RMS displacement, stratified jitter, Poisson disk, Sobol.
  std::vector<Method> methods = {Method::cnj, Method::jitter_matched, Method::jitter, Method::pds, Method::sobol};
  Protocol protocol = Protocol::fair;
  KnnBackend knn = KnnBackend::nanoflann;
  // cnj.domain is the run's domain, every method's (the fair protocol; the paper's is the cube): the
  // unit torus (the default), cube, ball, or sphere S^{N-1} (N >= 3: methods cnj and random, geodesic
  // statistics). The sets are measured in its metric (minimum image on the torus). cnj.domain_mode: how
  // CNJ meets a boundary.
  CnjOptions cnj;
  DomainKind domain() const { return cnj.domain; }
  // 0: fair: the largest radius that reaches the count, found by the sampler (sampling/poisson_disk.hpp's
  // poisson_disk_reaching); paper: 0.1. Otherwise this radius, stopping at the count.
  double pds_radius = 0.0;
  int pds_candidates = 30;
  Scramble scramble = Scramble::owen;
  bool compute_statistics = true;  // false (--no-stats): generate the sets only
  bool compute_rdf = false;
  RdfOptions rdf;
  // Whether the sets are measured on the torus (minimum-image distances, the RDF without edges): the
  // run's domain decides.
  bool periodic_statistics() const { return cnj.domain == DomainKind::torus; }
  double max_memory_gib = 0.0;  // 0: 80% of the machine's memory
  // Made in slabs (experiment/streamed_sampling.hpp): validate() checks the streamed run's memory and
  // what it refuses instead of the in-memory sets'. stream_slabs: the slab count, 0 = automatic.
  bool stream = false;
  int stream_slabs = 0;
  // 0: every method takes the lattice's count, the sites of the K^N lattice in the domain (Sobol under
  // the paper protocol: 2^round(log2 K^N)). Otherwise the methods without a lattice (pds, sobol, random,
  // halton, lhs) are asked for exactly this many points, and `grid` should be grid_for_count(dimension,
  // count) (sampling/lattice.hpp).
  std::uint64_t count = 0;

  // Throws std::invalid_argument with a message naming the option, including when the point sets
  // would not fit in memory (saying how much they need and how to override).
  void validate() const;

  LatticeSpec lattice() const { return {dimension, grid, protocol}; }
  // Sets the protocol and what it fixes: paper puts the run in the cube (cnj.domain), CNJ in drop mode,
  // and its steps at Section 5.1's one RK4 step unless steps were chosen (cnj.trace.steps not 0).
  void use_protocol(Protocol chosen);
};

// What the user should know before the run: Sobol asked for a count that is not a power of two (its
// balance properties need 2^m points, as SciPy warns), a -n count that the lattice methods cannot
// match exactly. One line each, without the program's name.
std::vector<std::string> sampling_warnings(const SampleConfig& config);

// Stages a run_sampling call reports (generation, statistics, RDF per method), for a [k/n] counter.
int sampling_stage_count(const SampleConfig& config);
// The expected cost of each of those stages, in their order (points x a per-method factor measured
// against the statistics), for the progress line's ETA.
std::vector<double> sampling_stage_weights(const SampleConfig& config);
// A method's expected generation cost per point against its nearest-neighbour statistics' (measured in
// 5D and 7D, 1e5-3e5 points, 2 threads: CNJ 2-4x, Poisson disk 3-5x, jitter and Halton a quarter or
// less, the others a few percent); the RDF costs about 4 times the statistics.
double sampling_generation_cost(Method method);

// What one method is asked for under the configured protocol.
struct MethodPlan {
  Method method;
  std::uint64_t requested = 0;  // points asked for (PDS may place fewer, CNJ may drop some)
  // Where its points live and are measured: the run's unit domain (fair); under the paper protocol
  // the cube its lattice's cells fill (LatticeSpec::cells) or the paper's box [0, 0.1 K]^N.
  Domain domain;
  double pds_radius = 0.0;  // 0: searched (fair), the largest that reaches `requested`
};
MethodPlan plan_method(const SampleConfig& config, Method method);

// Bytes the largest point set and its statistics need at the peak (about).
double estimated_peak_bytes(const SampleConfig& config);
// The memory limit of --max-memory: max_memory_gib, or 80% of the machine's memory when it is 0.
double memory_limit_bytes(const SampleConfig& config);

// Facts of how a set was made, each in the unit of the option it comes from; empty where the method
// has no such thing.
struct GenerationFacts {
  std::optional<double> frequency;        // cnj: noise cycles per lattice spacing (--cycles-per-spacing)
  std::optional<double> field_frequency;  // cnj: the field's cycles per unit length, frequency / spacing
  std::optional<double> trace_time;       // cnj: t = step_scale * dbar(N) * spacing, length units
  std::optional<std::uint64_t> dropped;   // cnj: points that left [0,1]^N
  std::optional<std::uint64_t> skipped_updates;  // cnj: reprojection updates rejected
  std::optional<std::uint64_t> retraced;      // cnj: traces repeated with finer steps to stay in the domain
  std::optional<std::uint64_t> kept_at_site;  // cnj: points left at their site when no retrace stayed inside
  std::optional<double> half_width;       // jitter: the offset's half-width, length units
  std::optional<double> radius;           // pds: the disk radius, length units (the one found, when searched)
  std::optional<bool> saturated;          // pds: the active list emptied before `requested` points
};

struct MethodResult {
  MethodPlan plan;
  PointSet points;
  std::uint64_t point_count = 0;  // points.size() after generation (kept when the points are released)
  GenerationFacts facts;
  bool measured = false;  // `nearest` holds statistics (false with compute_statistics off)
  NearestNeighbourSummary nearest;
  // Lattice methods (cnj, jitter): how far points moved from their sites (every traced point).
  std::optional<LatticeDisplacementSummary> displacement;
  std::optional<RdfCurve> rdf;
  double seconds_generate = 0.0;
  double seconds_stats = 0.0;
  std::string notes;  // words only: the noise basis, the scrambling, why PDS stopped
};

// What a run keeps from one method for the next: CNJ's RMS displacement, which jitter-matched
// reaches (jitter-matched runs CNJ itself, without keeping its points, when CNJ has not run yet).
struct SamplingContext {
  std::optional<double> cnj_rms_displacement;
};

// Fills result.points, result.notes and (for lattice methods) result.displacement for result.plan.
void generate_points(const SampleConfig& config, MethodResult& result, SamplingContext& context,
                     const StageProgress& progress = {});
// The same with a context of its own.
void generate_points(const SampleConfig& config, MethodResult& result, const StageProgress& progress = {});

// One point set of `method` under `config` (config.methods is not consulted): validates, plans and
// generates exactly as run_sampling does, without the statistics. Keeps the points.
MethodResult sample_method(const SampleConfig& config, Method method);

// Runs every configured method: generate, then nearest-neighbour statistics (and the RDF if asked).
// `keep_points`: keep each point set in its result (otherwise it is released after its statistics).
std::vector<MethodResult> run_sampling(const SampleConfig& config, bool keep_points, const StageProgress& progress = {},
                                       const std::function<void(const MethodResult&)>& on_result = {});

// CSV text. Stats: one row per method, data rows only, header dim,grid,method,points,nn_min,nn_q01,
// nn_median,nn_mean,nn_median_scaled,rms_displacement,median_displacement,frac_unmoved,neighbour_disorder,
// lattice_order,seconds_generate,seconds_stats,seed,protocol,domain,domain_side,requested,
// cycles_per_spacing,field_frequency,trace_time,dropped,skipped_updates,retraced,kept_at_site,half_width,
// radius,saturated,noise,mode,scramble,notes (realizations: experiment/realizations.hpp's
// realization_summary_csv makes the summary from these rows). A column that does not apply is empty: the
// displacement columns for methods without a lattice (pds, sobol, random, halton, lhs), the
// GenerationFacts columns for the other methods, noise and mode but for CNJ, scramble but for Sobol and
// Halton, the seconds with `timing` off (so that two runs with the same seed give the same bytes). Every
// real number has a decimal point or an exponent (io/csv.hpp's format_real: 9 significant digits), times
// have 6 decimals, every count is an integer.
std::string stats_csv_header();
std::string stats_csv_row(const SampleConfig& config, const MethodResult& result, bool timing = true);
// RDF: header dim,method,r,g and one row per bin.
std::string rdf_csv_header();
std::string rdf_csv_rows(const SampleConfig& config, const MethodResult& result);

}  // namespace dfvn
