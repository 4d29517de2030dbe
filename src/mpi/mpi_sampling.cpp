#include "dfvn/mpi/mpi_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <unistd.h>

#include <fmt/format.h>

#include "dfvn/core/message_text.hpp"
#include "dfvn/core/stopwatch.hpp"
#include "dfvn/experiment/streamed_sampling.hpp"
#include "dfvn/mpi/mpi_exact.hpp"
#include "dfvn/mpi/mpi_neighbours.hpp"
#include "dfvn/mpi/mpi_point_file.hpp"
#include "dfvn/sampling/jitter.hpp"
#include "dfvn/stats/distance_scale.hpp"

namespace dfvn {

namespace {

bool is_lattice(Method m) { return m == Method::cnj || m == Method::jitter; }

std::uint64_t layer_size(const SampleConfig& config) {
  std::uint64_t layer = 1;
  for (int a = 0; a + 1 < config.dimension; ++a) layer *= static_cast<std::uint64_t>(config.grid);
  return layer;
}

std::uint64_t slab_rows(const SampleConfig& config, const MethodPlan& plan, int count) {
  return is_lattice(plan.method) ? layer_size(config) * static_cast<std::uint64_t>(config.grid / count)
                                 : (plan.requested + count - 1) / count;
}

// The displacement sums of a lattice method (LatticeDisplacementSums), added by each rank to the state
// passed along the ranks, in the order of the one-process stream's DisplacementStream: every
// accumulator in index order. The state: points, included, unmoved, pairs, sum2, pair_sum2[N],
// bragg[N] (re, im), and the last layer of the rows so far (layer x N, with a flag).
class DisplacementState {
 public:
  DisplacementState(const SampleConfig& config, double spacing)
      : n_(config.dimension), grid_(config.grid), layer_(layer_size(config)), spacing_(spacing) {}
  std::size_t size() const { return 5 + 3 * static_cast<std::size_t>(n_) + 1 + layer_ * n_; }
  void add(std::vector<double>& state, const std::vector<double>& u, std::uint64_t first) const {
    const std::uint64_t rows = u.size() / static_cast<std::size_t>(n_);
    if (rows == 0) return;
    // Counts travel as doubles: exact below 2^53.
    double& points = state[0];
    double& included = state[1];
    double& unmoved = state[2];
    double& pairs = state[3];
    double& sum2 = state[4];
    double* pair_sum2 = &state[5];
    double* bragg = &state[5 + n_];
    double& have_previous = state[5 + 3 * n_];
    double* previous = &state[6 + 3 * n_];
    const auto at = [&](std::uint64_t r) { return u.data() + r * n_; };
    for (std::uint64_t r = 0; r < rows; ++r) {
      double r2 = 0.0;
      for (int a = 0; a < n_; ++a) r2 += at(r)[a] * at(r)[a];
      sum2 += r2;
      unmoved += std::sqrt(r2) < 0.01 * spacing_;
    }
    points += static_cast<double>(rows);
    included += static_cast<double>(rows);
    std::uint64_t stride = 1;
    for (int a = 0; a + 1 < n_; ++a) {
      double& sum = pair_sum2[a];
      for (std::uint64_t r = 0; r < rows; ++r) {
        if (((first + r) / stride) % static_cast<std::uint64_t>(grid_) == static_cast<std::uint64_t>(grid_ - 1)) continue;
        add_squared_difference(sum, at(r), at(r + stride));
        pairs += 1.0;
      }
      stride *= static_cast<std::uint64_t>(grid_);
    }
    double& last = pair_sum2[n_ - 1];
    if (have_previous != 0.0)
      for (std::uint64_t r = 0; r < layer_; ++r) {
        add_squared_difference(last, previous + r * n_, at(r));
        pairs += 1.0;
      }
    for (std::uint64_t r = 0; r + layer_ < rows; ++r) {
      add_squared_difference(last, at(r), at(r + layer_));
      pairs += 1.0;
    }
    std::copy(u.end() - static_cast<std::ptrdiff_t>(layer_ * n_), u.end(), previous);
    have_previous = 1.0;
    for (int a = 0; a < n_; ++a) {
      std::complex<double> b(bragg[2 * a], bragg[2 * a + 1]);
      for (std::uint64_t r = 0; r < rows; ++r) b += std::polar(1.0, 2.0 * std::numbers::pi * at(r)[a] / spacing_);
      bragg[2 * a] = b.real();
      bragg[2 * a + 1] = b.imag();
    }
  }
  LatticeDisplacementSums sums(const std::vector<double>& state) const {
    LatticeDisplacementSums s;
    s.points = static_cast<std::uint64_t>(state[0]);
    s.included = static_cast<std::uint64_t>(state[1]);
    s.unmoved = static_cast<std::uint64_t>(state[2]);
    s.pairs = static_cast<std::uint64_t>(state[3]);
    s.sum2 = state[4];
    s.pair_sum2.assign(state.begin() + 5, state.begin() + 5 + n_);
    for (int a = 0; a < n_; ++a) s.bragg.emplace_back(state[5 + n_ + 2 * a], state[6 + n_ + 2 * a]);
    return s;
  }

 private:
  void add_squared_difference(double& sum, const double* a, const double* b) const {
    for (int k = 0; k < n_; ++k) sum += (a[k] - b[k]) * (a[k] - b[k]);
  }
  int n_, grid_;
  std::uint64_t layer_;
  double spacing_;
};

void fail_here(int rank, const char* where) {
  std::fprintf(stderr, "dfvn-sample-mpi: error: rank %d stops %s (DFVN_MPI_FAIL_RANK, a test hook)\n", rank, where);
  std::fflush(stderr);
  ::_exit(3);
}

MethodResult run_mpi_method(const RankSlabs& ranks, const SampleConfig& config, const MethodPlan& plan,
                            const std::function<std::string(Method)>& point_path, PointFormat format,
                            const StageProgress& progress, int fail_rank, bool& failed_once) {
  const int n = config.dimension;
  MethodResult result;
  result.plan = plan;
  const std::uint64_t rows_per_slab = slab_rows(config, plan, ranks.slabs);
  const auto first_row = [&](int s) { return std::min(plan.requested, rows_per_slab * static_cast<std::uint64_t>(s)); };
  const int my_slab = ranks.first_slab(ranks.rank), end_slab = ranks.first_slab(ranks.rank + 1);
  const std::uint64_t first = first_row(my_slab);
  const std::uint64_t rows = first_row(end_slab) - first;
  const LatticeSpec lattice = config.lattice();
  const Domain domain = plan.domain;
  if (config.compute_statistics && domain_scale(domain.side) != 1.0)
    throw std::invalid_argument("--stream measures sets of ordinary side only");

  const std::string name(to_string(plan.method));
  if (progress) progress(name, 0.0);
  Stopwatch stopwatch;
  Slab part;
  // A slab at a time (the same rows as one range: every point depends only on its index), so that rank 0
  // can report its progress; the rank's rows appended in order.
  run_everywhere(ranks.comm, [&] {
    part = generate_slab(config, plan, first, 0);
    part.points.coordinates.reserve(rows * static_cast<std::uint64_t>(n));
    if (is_lattice(plan.method)) part.displacements.reserve(rows * static_cast<std::uint64_t>(n));
    for (int s = my_slab; s < end_slab; ++s) {
      const std::uint64_t slab_first = first_row(s), slab_count = first_row(s + 1) - slab_first;
      if (slab_count == 0) continue;
      Slab slab = generate_slab(config, plan, slab_first, slab_count);
      part.points.coordinates.insert(part.points.coordinates.end(), slab.points.coordinates.begin(),
                                     slab.points.coordinates.end());
      part.displacements.insert(part.displacements.end(), slab.displacements.begin(), slab.displacements.end());
      part.dropped += slab.dropped;
      part.skipped += slab.skipped;
      part.retraced += slab.retraced;
      part.kept += slab.kept;
      part.trace_time = slab.trace_time;
      part.field_frequency = slab.field_frequency;
      if (progress) progress(name, static_cast<double>(s + 1 - my_slab) / static_cast<double>(end_slab - my_slab));
    }
  });
  // Counts: the output rows of the ranks below, the totals.
  unsigned long long counts[5] = {part.points.size(), part.dropped, part.skipped, part.retraced, part.kept}, totals[5];
  MPI_Allreduce(counts, totals, 5, MPI_UNSIGNED_LONG_LONG, MPI_SUM, ranks.comm);
  unsigned long long accepted_here = part.points.size();
  std::vector<unsigned long long> accepted_of(static_cast<std::size_t>(ranks.size));
  MPI_Allgather(&accepted_here, 1, MPI_UNSIGNED_LONG_LONG, accepted_of.data(), 1, MPI_UNSIGNED_LONG_LONG, ranks.comm);
  std::vector<std::uint64_t> first_rows(static_cast<std::size_t>(ranks.size) + 1, 0);
  for (int r = 0; r < ranks.size; ++r) first_rows[r + 1] = first_rows[r] + accepted_of[r];
  const std::uint64_t my_first = first_rows[ranks.rank];
  const std::uint64_t accepted = totals[0];
  double facts_in[2] = {part.trace_time, part.field_frequency}, facts_out[2];
  MPI_Allreduce(facts_in, facts_out, 2, MPI_DOUBLE, MPI_MAX, ranks.comm);

  result.point_count = accepted;
  GenerationFacts& facts = result.facts;
  if (plan.method == Method::cnj) {
    facts.frequency = config.cnj.frequency;
    facts.field_frequency = facts_out[1];
    facts.trace_time = facts_out[0];
    facts.dropped = totals[1];
    facts.skipped_updates = totals[2];
    facts.retraced = totals[3];
    facts.kept_at_site = totals[4];
    result.notes = fmt::format("{} noise; {}", to_string(config.cnj.noise), to_string(config.cnj.domain_mode));
    if (config.cnj.field == FieldKind::curl) result.notes += "; curl noise field, no reprojection";
  } else if (plan.method == Method::jitter) {
    facts.half_width = jitter_half_width(lattice);
  } else if (plan.method == Method::sobol) {
    result.notes = fmt::format("{} scrambling", to_string(config.scramble));
  }
  if (is_lattice(plan.method)) {
    const double spacing =
        plan.method == Method::cnj ? cnj_lattice(lattice, config.cnj.domain).spacing() : lattice.spacing();
    const DisplacementState displacement(config, spacing);
    std::vector<double> state(displacement.size(), 0.0);
    pass_along_ranks(ranks.comm, state, [&](std::vector<double>& s) { displacement.add(s, part.displacements, first); });
    std::vector<double> lengths(part.displacements.size() / static_cast<std::size_t>(n));
    for (std::size_t r = 0; r < lengths.size(); ++r) {
      double r2 = 0.0;
      for (int a = 0; a < n; ++a) r2 += part.displacements[r * n + a] * part.displacements[r * n + a];
      lengths[r] = std::sqrt(r2);
    }
    std::sort(lengths.begin(), lengths.end());
    const LatticeDisplacementSums sums = displacement.sums(state);
    const double median = distributed_median(ranks.comm, lengths, sums.included);
    result.displacement = finish_lattice_displacements(n, spacing, sums, median);
  }
  part.displacements = {};
  result.seconds_generate = stopwatch.seconds();
  if (config.compute_statistics && accepted < 2)
    throw std::invalid_argument(fmt::format("the {} point set has {} point(s) ({}); the statistics need at least 2", name,
                                            accepted, facts.dropped ? fmt::format("{} dropped", *facts.dropped) : result.notes));
  if (point_path) {
    MpiPointFile file(ranks.comm, point_path(plan.method), format);
    file.write(part.points);
    if (ranks.rank == fail_rank && !failed_once) fail_here(ranks.rank, "after writing its share of the points");
    file.commit();
  }
  if (!config.compute_statistics) return result;
  const std::string stage = name + " statistics";
  if (progress) progress(stage, 0.0);
  stopwatch.restart();
  if (ranks.rank == fail_rank && !failed_once) fail_here(ranks.rank, "before the statistics");
  failed_once = true;
  std::unique_ptr<OwnedPoints> owned;
  std::vector<std::pair<std::uint64_t, double>> pairs;
  run_everywhere(ranks.comm, [&] {
    owned = std::make_unique<OwnedPoints>(ranks, part.points, my_first, domain, domain.periodic());
    part.points = {};
    pairs = owned->nearest_distances(first_rows, accepted, config.knn, config.threads, [&](double f) {
      if (progress) progress(stage, f);
    });
  });
  std::vector<double> state{0.0};
  pass_along_ranks(ranks.comm, state, [&](std::vector<double>& s) {
    for (const auto& p : pairs) s[0] += p.second;  // in index order, as summarize_nearest_neighbours
  });
  std::vector<double> sorted(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) sorted[k] = pairs[k].second;
  std::sort(sorted.begin(), sorted.end());
  result.nearest = summarize_nearest_neighbours(accepted, state[0], distributed_order_statistics(ranks.comm, sorted, accepted),
                                                domain.measure(n), n);
  result.measured = true;
  result.seconds_stats = stopwatch.seconds();
  if (config.compute_rdf) {
    const std::string rdf_stage = name + " rdf";
    if (progress) progress(rdf_stage, 0.0);
    const RdfOptions& rdf = config.rdf;
    run_everywhere(ranks.comm, [&] {
      result.rdf = owned->radial_distribution(rdf, config.seed, accepted, config.threads, [&](double f) {
        if (progress) progress(rdf_stage, f);
      });
    });
  }
  return result;
}

}  // namespace

int mpi_slab_count(const SampleConfig& config, int requested, int ranks) {
  const int automatic = stream_slab_count(config, requested);
  if (requested > 0) return automatic;
  const bool lattice = std::any_of(config.methods.begin(), config.methods.end(), is_lattice);
  const int wanted = std::max(automatic, ranks);
  if (lattice) {
    for (int s = wanted; s <= config.grid; ++s)
      if (config.grid % s == 0) return s;
    return config.grid;
  }
  std::uint64_t fewest_points = std::numeric_limits<std::uint64_t>::max();
  for (Method m : config.methods) fewest_points = std::min(fewest_points, plan_method(config, m).requested);
  return static_cast<int>(std::min<std::uint64_t>(static_cast<std::uint64_t>(wanted), fewest_points));
}

double mpi_rank_peak_bytes(const SampleConfig& config, int slabs, int ranks) {
  const int slabs_per_rank = (slabs + ranks - 1) / ranks;
  double peak = 0.0;
  for (Method m : config.methods) {
    const MethodPlan plan = plan_method(config, m);
    const double rows = static_cast<double>(std::min<std::uint64_t>(
        plan.requested, slab_rows(config, plan, slabs) * static_cast<std::uint64_t>(slabs_per_rank)));
    // The RDF's halo reaches r_max (by default 2.5 mean spacings) each side of the rank's range, held
    // with the rank's points in one set (sample --stream's estimate of a halo point).
    double halo = 0.0;
    if (config.compute_rdf && config.compute_statistics) {
      const double total = static_cast<double>(plan.requested);
      const double r = config.rdf.r_max > 0.0 ? config.rdf.r_max / plan.domain.side
                                              : 2.5 / std::pow(total, 1.0 / config.dimension);
      halo = std::min(total - rows, 2.0 * std::min(1.0, r) * total);
    }
    peak = std::max(peak, rows * (56.0 * config.dimension + 64.0) + halo * (16.0 * config.dimension + 48.0));
  }
  return peak;
}

int check_mpi_run(const SampleConfig& config, int requested_slabs, int ranks) {
  config.validate();
  if (const std::string why = stream_refusal(config); !why.empty()) throw std::invalid_argument(why);
  const int count = mpi_slab_count(config, requested_slabs, ranks);
  const double need = mpi_rank_peak_bytes(config, count, ranks), limit = memory_limit_bytes(config);
  if (need > limit)
    throw std::invalid_argument(fmt::format("a rank's share of the points needs about {} of memory (limit {}): run on more "
                                            "ranks (or raise --max-memory)",
                                            byte_size(need), byte_size(limit)));
  return count;
}

std::vector<MethodResult> run_mpi_sampling(MPI_Comm comm, const SampleConfig& config, int slabs,
                                           const std::function<std::string(Method)>& point_path, PointFormat format,
                                           const StageProgress& progress, int fail_rank) {
  int size = 1, count = 0;
  MPI_Comm_size(comm, &size);
  run_everywhere(comm, [&] { count = check_mpi_run(config, slabs, size); });
  const RankSlabs ranks(comm, count);
  std::vector<MethodResult> results;
  bool failed_once = false;
  for (Method m : config.methods) {
    MethodResult r;
    run_everywhere(comm, [&] {
      r = run_mpi_method(ranks, config, plan_method(config, m), point_path, format, progress, fail_rank, failed_once);
    });
    results.push_back(std::move(r));
  }
  return results;
}

}  // namespace dfvn
