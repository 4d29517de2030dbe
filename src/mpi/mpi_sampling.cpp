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
#include "dfvn/mpi/mpi_point_file.hpp"
#include "dfvn/sampling/jitter.hpp"
#include "dfvn/stats/distance_scale.hpp"

namespace dfvn {

namespace {

bool is_lattice(Method m) { return m == Method::cnj || m == Method::jitter; }

struct Ranks {
  MPI_Comm comm;
  int rank = 0, size = 1;
  explicit Ranks(MPI_Comm c) : comm(c) {
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
  }
  // Rank r's slabs: [first_slab(r), first_slab(r + 1)).
  int first_slab(int r, int slabs) const {
    return static_cast<int>(static_cast<long long>(r) * slabs / size);
  }
  int rank_of_slab(int s, int slabs) const {
    int r = 0;
    while (r + 1 < size && first_slab(r + 1, slabs) <= s) ++r;
    return r;
  }
};

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

// Records of (index bits, x_0 .. x_{N-1}) exchanged between ranks.
std::vector<double> all_to_all(MPI_Comm comm, const std::vector<std::vector<double>>& out) {
  const int size = static_cast<int>(out.size());
  std::vector<int> send_counts(size), receive_counts(size), send_at(size), receive_at(size);
  std::vector<double> send;
  for (int r = 0; r < size; ++r) {
    if (out[r].size() > static_cast<std::size_t>(std::numeric_limits<int>::max()) - send.size())
      throw std::runtime_error("dfvn-sample-mpi: more than 2^31 values between two ranks: run on more ranks");
    send_at[r] = static_cast<int>(send.size());
    send_counts[r] = static_cast<int>(out[r].size());
    send.insert(send.end(), out[r].begin(), out[r].end());
  }
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, comm);
  long long total = 0;
  for (int r = 0; r < size; ++r) {
    receive_at[r] = static_cast<int>(total);
    total += receive_counts[r];
  }
  std::vector<double> in(static_cast<std::size_t>(total));
  MPI_Alltoallv(send.data(), send_counts.data(), send_at.data(), MPI_DOUBLE, in.data(), receive_counts.data(),
                receive_at.data(), MPI_DOUBLE, comm);
  return in;
}

std::vector<double> sendrecv(MPI_Comm comm, const std::vector<double>& out, int to, int from) {
  long long count = static_cast<long long>(out.size()), incoming = 0;
  MPI_Sendrecv(&count, 1, MPI_LONG_LONG, to, 81, &incoming, 1, MPI_LONG_LONG, from, 81, comm, MPI_STATUS_IGNORE);
  std::vector<double> in(static_cast<std::size_t>(incoming));
  MPI_Sendrecv(out.data(), static_cast<int>(count), MPI_DOUBLE, to, 82, in.data(), static_cast<int>(incoming), MPI_DOUBLE,
               from, 82, comm, MPI_STATUS_IGNORE);
  return in;
}

double tag_of(std::uint64_t index) {
  double tag;
  std::memcpy(&tag, &index, sizeof tag);
  return tag;
}
std::uint64_t index_of(double tag) {
  std::uint64_t index;
  std::memcpy(&index, &tag, sizeof index);
  return index;
}

// Every point's nearest-neighbour distance, returned to the rank that made the point, by index:
// (index, distance) pairs sorted by index. `first_rows[r]`: the first output row of rank r (P + 1 entries).
std::vector<std::pair<std::uint64_t, double>> nearest_distances(const Ranks& ranks, const SampleConfig& config,
                                                                const PointSet& mine, std::uint64_t my_first,
                                                                const std::vector<std::uint64_t>& first_rows,
                                                                int slabs, const Box& domain, std::uint64_t total) {
  const int n = config.dimension;
  const std::size_t record = static_cast<std::size_t>(n) + 1;
  const auto edge = [&](int s) { return domain.lo + domain.side * static_cast<double>(s) / static_cast<double>(slabs); };
  const auto bucket_of = [&](double z) {
    const double f = (z - domain.lo) / domain.side * static_cast<double>(slabs);
    if (!(f >= 0.0)) return 0;
    return static_cast<int>(std::min(std::floor(f), static_cast<double>(slabs - 1)));
  };
  // The points to the ranks owning their last coordinate's slab.
  std::vector<std::vector<double>> out(static_cast<std::size_t>(ranks.size));
  double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
  for (std::size_t i = 0; i < mine.size(); ++i) {
    const double* x = mine.point(i);
    zmin = std::min(zmin, x[n - 1]);
    zmax = std::max(zmax, x[n - 1]);
    std::vector<double>& o = out[static_cast<std::size_t>(ranks.rank_of_slab(bucket_of(x[n - 1]), slabs))];
    o.push_back(tag_of(my_first + i));
    o.insert(o.end(), x, x + n);
  }
  double extremes[2] = {zmin, -zmax}, global[2];
  MPI_Allreduce(extremes, global, 2, MPI_DOUBLE, MPI_MIN, ranks.comm);
  zmin = global[0];
  zmax = -global[1];
  const std::vector<double> owned = all_to_all(ranks.comm, out);
  const std::uint64_t queries = owned.size() / record;
  const int s0 = ranks.first_slab(ranks.rank, slabs), s1 = ranks.first_slab(ranks.rank + 1, slabs);
  const double range_lo = edge(s0), range_hi = edge(s1);
  // d: each owned point's distance; pending: the points whose distance is not yet known to be exact.
  std::vector<double> d(queries, std::numeric_limits<double>::quiet_NaN());
  std::vector<std::uint64_t> pending(queries);
  for (std::uint64_t q = 0; q < queries; ++q) pending[q] = q;
  double h = domain.side / std::pow(static_cast<double>(total), 1.0 / n);
  for (int attempt = 0;; ++attempt) {
    // The halo: from ranks r -+ k the points within h of this rank's range, k = 1, 2, ... while any rank
    // still sends a point (the sets shrink with k: the ranges move away).
    std::vector<double> halo;
    for (int k = 1; k < ranks.size; ++k) {
      const int up = ranks.rank + k < ranks.size ? ranks.rank + k : MPI_PROC_NULL;
      const int down = ranks.rank - k >= 0 ? ranks.rank - k : MPI_PROC_NULL;
      std::vector<double> to_up, to_down;
      const double up_lo = up != MPI_PROC_NULL ? edge(ranks.first_slab(up, slabs)) - h : 0.0;
      const double down_hi = down != MPI_PROC_NULL ? edge(ranks.first_slab(down + 1, slabs)) + h : 0.0;
      for (std::uint64_t q = 0; q < queries; ++q) {
        const double* r = owned.data() + q * record;
        const double z = r[n];
        if (up != MPI_PROC_NULL && z >= up_lo) to_up.insert(to_up.end(), r, r + record);
        if (down != MPI_PROC_NULL && z < down_hi) to_down.insert(to_down.end(), r, r + record);
      }
      int sent = !to_up.empty() || !to_down.empty(), any = 0;
      std::vector<double> from_down = sendrecv(ranks.comm, to_up, up, down);
      std::vector<double> from_up = sendrecv(ranks.comm, to_down, down, up);
      halo.insert(halo.end(), from_down.begin(), from_down.end());
      halo.insert(halo.end(), from_up.begin(), from_up.end());
      MPI_Allreduce(&sent, &any, 1, MPI_INT, MPI_MAX, ranks.comm);
      if (!any) break;
    }
    const double lo = range_lo - h, hi = range_hi + h;
    const bool all_below = lo <= zmin, all_above = hi > zmax;
    double needed = h;
    std::vector<std::uint64_t> still;
    if (!pending.empty()) {
      // The set: the pending points first, then every other loaded point (first attempt) or those within
      // the windows [z - d, z + d] of the pending points' last distances d (later attempts: a pending
      // point's nearest neighbour is no farther than the point found before, which is still loaded, so
      // it lies in its window; only the few points near the range's edges are measured again).
      std::vector<std::pair<double, double>> windows;
      if (attempt > 0) {
        for (std::uint64_t q : pending) {
          const double z = owned[q * record + n], reach = d[q] * (1.0 + 1e-6) + 1e-9 * domain.side;
          windows.emplace_back(std::isfinite(reach) ? z - reach : -std::numeric_limits<double>::infinity(),
                               std::isfinite(reach) ? z + reach : std::numeric_limits<double>::infinity());
        }
        std::sort(windows.begin(), windows.end());
        std::vector<std::pair<double, double>> merged;
        for (const auto& w : windows)
          if (!merged.empty() && w.first <= merged.back().second) merged.back().second = std::max(merged.back().second, w.second);
          else merged.push_back(w);
        windows = std::move(merged);
      }
      const auto in_windows = [&](double z) {
        if (attempt == 0) return true;
        auto it = std::upper_bound(windows.begin(), windows.end(), std::make_pair(z, std::numeric_limits<double>::infinity()));
        return it != windows.begin() && z <= std::prev(it)->second;
      };
      PointSet set{n, {}, domain};
      std::vector<char> is_pending(queries, 0);
      const auto add = [&](const double* r) { set.coordinates.insert(set.coordinates.end(), r + 1, r + record); };
      for (std::uint64_t q : pending) {
        is_pending[q] = 1;
        add(owned.data() + q * record);
      }
      for (std::uint64_t q = 0; q < queries; ++q)
        if (!is_pending[q] && in_windows(owned[q * record + n])) add(owned.data() + q * record);
      for (std::size_t k = 0; k < halo.size(); k += record)
        if (in_windows(halo[k + n])) add(halo.data() + k);
      if (set.size() < 2) {
        if (all_below && all_above) throw std::invalid_argument("the statistics need at least 2 points");
        needed = 2.0 * h;
        still = pending;
      } else {
        // Few pending points (later attempts): each against every point of the set, by distance_between, the
        // function through which the KD-trees report their distances too (the same bits); else the KD-tree.
        std::vector<double> found;
        if (static_cast<double>(pending.size()) * static_cast<double>(set.size()) <= 5e7) {
          found.assign(pending.size(), std::numeric_limits<double>::infinity());
          for (std::size_t j = 0; j < pending.size(); ++j)
            for (std::size_t k = 0; k < set.size(); ++k)
              if (k != j) found[j] = std::min(found[j], distance_between(set, j, k));
        } else {
          found = nearest_neighbour_distances(set, config.knn, config.threads);
        }
        // The one-process stream's rule (streamed_sampling.cpp, measure_bucket).
        constexpr double kSlack = 1e-9;
        const double width = hi - lo;
        for (std::size_t j = 0; j < pending.size(); ++j) {
          const std::uint64_t q = pending[j];
          d[q] = found[j];
          const double z = owned[q * record + n];
          const double margin = std::min(all_below ? std::numeric_limits<double>::infinity() : z - lo,
                                         all_above ? std::numeric_limits<double>::infinity() : hi - z);
          if (!(d[q] <= margin - kSlack * width)) {
            needed = std::max(needed, (h + d[q] - margin) * (1.0 + 1e-6) + 2.0 * kSlack * width);
            still.push_back(q);
          }
        }
      }
    }
    pending = std::move(still);
    double most = 0.0;
    MPI_Allreduce(&needed, &most, 1, MPI_DOUBLE, MPI_MAX, ranks.comm);
    if (most <= h) break;
    h = attempt < 4 ? most : 2.0 * h;
  }
  // Each distance back to the rank that made its point.
  std::vector<std::vector<double>> back(static_cast<std::size_t>(ranks.size));
  for (std::uint64_t q = 0; q < queries; ++q) {
    const std::uint64_t index = index_of(owned[q * record]);
    const int r = static_cast<int>(std::upper_bound(first_rows.begin(), first_rows.end(), index) - first_rows.begin()) - 1;
    back[static_cast<std::size_t>(r)].push_back(owned[q * record]);
    back[static_cast<std::size_t>(r)].push_back(d[q]);
  }
  const std::vector<double> in = all_to_all(ranks.comm, back);
  std::vector<std::pair<std::uint64_t, double>> pairs(in.size() / 2);
  for (std::size_t k = 0; k < pairs.size(); ++k) pairs[k] = {index_of(in[2 * k]), in[2 * k + 1]};
  std::sort(pairs.begin(), pairs.end());
  if (pairs.size() != mine.size()) throw std::logic_error("a point without its nearest-neighbour distance");
  for (std::size_t k = 0; k < pairs.size(); ++k)
    if (pairs[k].first != my_first + k) throw std::logic_error("a point without its nearest-neighbour distance");
  return pairs;
}

void fail_here(int rank, const char* where) {
  std::fprintf(stderr, "dfvn-sample-mpi: error: rank %d stops %s (DFVN_MPI_FAIL_RANK, a test hook)\n", rank, where);
  std::fflush(stderr);
  ::_exit(3);
}

MethodResult run_mpi_method(const Ranks& ranks, const SampleConfig& config, const MethodPlan& plan, int slab_count,
                            const std::function<std::string(Method)>& point_path, PointFormat format, int fail_rank,
                            bool& failed_once) {
  const int n = config.dimension;
  MethodResult result;
  result.plan = plan;
  const std::uint64_t rows_per_slab = slab_rows(config, plan, slab_count);
  const auto first_row = [&](int s) { return std::min(plan.requested, rows_per_slab * static_cast<std::uint64_t>(s)); };
  const std::uint64_t first = first_row(ranks.first_slab(ranks.rank, slab_count));
  const std::uint64_t rows = first_row(ranks.first_slab(ranks.rank + 1, slab_count)) - first;
  const LatticeSpec lattice = config.lattice();
  const Box domain = plan.method == Method::cnj ? Box{0.0, 1.0} : plan.domain;
  if (config.compute_statistics && domain_scale(domain.side) != 1.0)
    throw std::invalid_argument("--stream measures sets of ordinary side only");

  Stopwatch stopwatch;
  Slab part;
  run_everywhere(ranks.comm, [&] { part = generate_slab(config, plan, first, rows); });
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
    result.notes = fmt::format("{} noise; {} domain; {}", to_string(config.cnj.noise), to_string(config.cnj.domain),
                               to_string(config.cnj.domain_mode));
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
  const std::string name(to_string(plan.method));
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
  stopwatch.restart();
  if (ranks.rank == fail_rank && !failed_once) fail_here(ranks.rank, "before the statistics");
  failed_once = true;
  std::vector<std::pair<std::uint64_t, double>> pairs;
  run_everywhere(ranks.comm, [&] {
    pairs = nearest_distances(ranks, config, part.points, my_first, first_rows, slab_count, domain, accepted);
  });
  std::vector<double> state{0.0};
  pass_along_ranks(ranks.comm, state, [&](std::vector<double>& s) {
    for (const auto& p : pairs) s[0] += p.second;  // in index order, as summarize_nearest_neighbours
  });
  std::vector<double> sorted(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) sorted[k] = pairs[k].second;
  std::sort(sorted.begin(), sorted.end());
  result.nearest = summarize_nearest_neighbours(accepted, state[0], distributed_order_statistics(ranks.comm, sorted, accepted),
                                                domain.volume(n), n);
  result.measured = true;
  result.seconds_stats = stopwatch.seconds();
  return result;
}

}  // namespace

std::string mpi_refusal(const SampleConfig& config) {
  // sample --stream measures on the torus and the RDF since the stream2 merge; the ranks' halos do
  // neither yet (no wrap between the first and last rank, no r_max halo), so refuse rather than differ.
  if (config.periodic_statistics) return "dfvn-sample-mpi measures in the box: no periodic statistics (sample --stream --periodic has them)";
  if (config.compute_rdf) return "dfvn-sample-mpi computes no RDF (sample --stream --rdf does)";
  return stream_refusal(config);
}

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
    peak = std::max(peak, rows * (56.0 * config.dimension + 64.0));
  }
  return peak;
}

int check_mpi_run(const SampleConfig& config, int requested_slabs, int ranks) {
  config.validate();
  if (const std::string why = mpi_refusal(config); !why.empty()) throw std::invalid_argument(why);
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
                                           int fail_rank) {
  const Ranks ranks(comm);
  int count = 0;
  run_everywhere(comm, [&] { count = check_mpi_run(config, slabs, ranks.size); });
  std::vector<MethodResult> results;
  bool failed_once = false;
  for (Method m : config.methods) {
    MethodResult r;
    run_everywhere(comm, [&] {
      r = run_mpi_method(ranks, config, plan_method(config, m), count, point_path, format, fail_rank, failed_once);
    });
    results.push_back(std::move(r));
  }
  return results;
}

}  // namespace dfvn
