// The sampling experiment of Section 5.1: generate the configured point sets and measure them.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sampling/curl_noise_jitter.hpp"
#include "sampling/lattice.hpp"
#include "sampling/point_set.hpp"
#include "sampling/sobol.hpp"
#include "sampling/sphere_jitter.hpp"
#include "stats/lattice_displacement.hpp"
#include "stats/nearest_neighbour.hpp"
#include "stats/radial_distribution.hpp"

namespace dfvn {

struct SampleConfig {
  int dimension = 7;
  int grid = 6;
  std::uint64_t seed = 1;
  int threads = 0;
  std::vector<Method> methods = {Method::cnj, Method::jitter, Method::pds, Method::sobol};
  Protocol protocol = Protocol::paper;
  KnnBackend knn = KnnBackend::nanoflann;
  CnjOptions cnj;  // cnj.domain and cnj.domain_mode: where CNJ's points stay and how
  // sphere: methods cnj and random on the unit sphere S^{N-1} (N >= 3), geodesic statistics.
  Surface on = Surface::none;
  double pds_radius = 0.0;  // 0: the protocol's (paper: 0.1; unit: 1/K)
  int pds_candidates = 30;
  Scramble scramble = Scramble::owen;
  bool compute_rdf = false;
  RdfOptions rdf;
  double max_memory_gib = 0.0;  // 0: 80% of the machine's memory
  // 0: every method takes the lattice's count (Sobol under the paper protocol: 2^round(log2 K^N)).
  // Otherwise the methods without a lattice (pds, sobol, random, halton, lhs) are asked for exactly
  // this many points, and `grid` should be grid_for_count(dimension, count) (sampling/lattice.hpp).
  std::uint64_t count = 0;

  // Throws std::invalid_argument with a message naming the option, including when the point sets
  // would not fit in memory (saying how much they need and how to override).
  void validate() const;

  LatticeSpec lattice() const { return {dimension, grid, protocol}; }
};

// What one method is asked for under the configured protocol.
struct MethodPlan {
  Method method;
  std::uint64_t requested = 0;  // points asked for (PDS may place fewer, CNJ may drop some)
  Box domain;
  double pds_radius = 0.0;
};
MethodPlan plan_method(const SampleConfig& config, Method method);

// Bytes the largest point set and its statistics need at the peak (about).
double estimated_peak_bytes(const SampleConfig& config);

struct MethodResult {
  MethodPlan plan;
  PointSet points;
  NearestNeighbourSummary nearest;
  // Lattice methods (cnj, jitter): how far points moved from their sites (every traced point).
  std::optional<LatticeDisplacementSummary> displacement;
  std::optional<RdfCurve> rdf;
  double seconds_generate = 0.0;
  double seconds_stats = 0.0;
  std::string notes;  // e.g. how many points CNJ dropped, whether PDS saturated
};

// Progress: stage name and fraction done; called from the calling thread only.
using StageProgress = std::function<void(std::string_view stage, double fraction)>;

// Fills result.points, result.notes and (for lattice methods) result.displacement for result.plan.
void generate_points(const SampleConfig& config, MethodResult& result, const StageProgress& progress = {});

// One point set of `method` under `config` (config.methods is not consulted): validates, plans and
// generates exactly as run_sampling does, without the statistics. Keeps the points.
MethodResult sample_method(const SampleConfig& config, Method method);

// Runs every configured method: generate, then nearest-neighbour statistics (and the RDF if asked).
// `keep_points`: keep each point set in its result (otherwise it is released after its statistics).
std::vector<MethodResult> run_sampling(const SampleConfig& config, bool keep_points, const StageProgress& progress = {},
                                       const std::function<void(const MethodResult&)>& on_result = {});

// CSV text. Stats: one row per method, header dim,grid,method,points,nn_min,nn_q01,nn_median,nn_mean,
// nn_median_scaled,rms_displacement,median_displacement,frac_unmoved,neighbour_disorder,lattice_order,
// seconds_generate,seconds_stats,seed,protocol,domain_side,requested,notes; the displacement columns
// are empty for methods without a lattice (pds, sobol, random).
std::string stats_csv_header();
std::string stats_csv_row(const SampleConfig& config, const MethodResult& result);
// RDF: header dim,method,r,g and one row per bin.
std::string rdf_csv_header();
std::string rdf_csv_rows(const SampleConfig& config, const MethodResult& result);

}  // namespace dfvn
