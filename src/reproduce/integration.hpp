// The paper's open question (Section 6.1): does curl noise jittering help to integrate functions in
// higher dimensions? Every method's point sets integrate Genz's six test families (equal weights,
// Q = mean of f over the set) and are judged by the RMS relative error over realizations.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dfvn/quadrature/genz.hpp"
#include "dfvn/reproduce/reproduce.hpp"

namespace dfvn {

struct IntegrationConfig {
  std::vector<int> dimensions = {3, 4, 5, 6, 7};
  int realizations = 16;  // seeds s..s+R-1; each draws its own point sets and integrand parameters
  std::uint64_t seed = 1;
  int threads = 0;
  std::uint64_t max_points = 1u << 15;  // the largest lattice K^N per dimension
  std::vector<Method> methods = {Method::cnj,    Method::jitter, Method::pds, Method::sobol,
                                 Method::random, Method::halton, Method::lhs};
  std::string out_dir = "out/integration";
  // Throws std::invalid_argument naming the option: among others, a method named twice and a
  // --max-points below a dimension's smallest lattice (2^7 = 128 points in 7D).
  void validate() const;
};

// The lattice sizes K of one dimension: up to 5 values, roughly evenly spaced in log K^N, from the
// smallest K with K^N >= 64 to the largest with K^N <= max_points (validate() refuses a max_points
// below the smallest).
std::vector<int> integration_grids(int dimension, std::uint64_t max_points);

struct IntegrationCell {
  int dimension = 0;
  GenzFamily family = GenzFamily::oscillatory;
  Method method = Method::cnj;
  int grid = 0;
  double points = 0.0;              // mean count over realizations (CNJ drops some, PDS places fewer)
  double rms_relative_error = 0.0;  // sqrt(mean_r ((Q_r - I_r) / I_r)^2)
  double standard_error = 0.0;      // of the RMS, by the delta method: sd(e^2) / (2 RMS sqrt(R))
};

struct IntegrationSlope {
  int dimension = 0;
  GenzFamily family = GenzFamily::oscillatory;
  Method method = Method::cnj;
  // Least-squares slope of log RMS error against log points (random: -1/2); none from fewer than two
  // sizes with different point counts, or when an error is 0.
  std::optional<double> slope;
};

struct IntegrationResult {
  IntegrationConfig config;
  std::vector<IntegrationCell> cells;
  std::vector<IntegrationSlope> slopes;
};

// `progress`: one stage per dimension, method and size ("5D cnj K=6"), its fraction the realizations
// done; integration_stage_weights gives their expected costs in that order.
IntegrationResult run_integration(const IntegrationConfig& config, const StageProgress& progress = {});
std::vector<double> integration_stage_weights(const IntegrationConfig& config);

// DIR/integration.csv (the cells), DIR/integration_slopes.csv, DIR/integration.md (tables and a
// reading) and, with gnuplot, DIR/integration_<N>d.png (scripts/integration.gp). Returns the
// Markdown; throws PlotError when gnuplot fails.
std::string write_integration(const IntegrationResult& result, const Log& log);
// The files write_integration writes into config.out_dir (the figures only with gnuplot).
std::vector<std::string> integration_output_files(const IntegrationConfig& config);
std::string integration_markdown(const IntegrationResult& result);

}  // namespace dfvn
