#include "dfvn/mpi/mpi_neighbours.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "dfvn/core/interval_union.hpp"
#include "dfvn/mpi/mpi_exact.hpp"
#include "dfvn/stats/periodic_neighbours.hpp"

namespace dfvn {

namespace {

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

}  // namespace

RankSlabs::RankSlabs(MPI_Comm c, int slab_count) : comm(c), slabs(slab_count) {
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
}

int RankSlabs::rank_of_slab(int s) const {
  // The last rank whose first slab is at most s (first_slab grows with r).
  int lo = 0, hi = size - 1;
  while (lo < hi) {
    const int mid = lo + (hi - lo + 1) / 2;
    if (first_slab(mid) <= s) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

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

OwnedPoints::OwnedPoints(const RankSlabs& ranks, const PointSet& mine, std::uint64_t my_first, const Domain& domain,
                         bool periodic)
    : ranks_(ranks), n_(mine.dimension), domain_(domain), periodic_(periodic) {
  const int n = n_, slabs = ranks_.slabs;
  // sample --stream's buckets (NearestStream::bucket_of), slab s on rank_of_slab(s).
  const auto bucket_of = [&](double z) {
    const double f = (z - domain_.lo) / domain_.side * static_cast<double>(slabs);
    if (!(f >= 0.0)) return 0;
    return static_cast<int>(std::min(std::floor(f), static_cast<double>(slabs - 1)));
  };
  std::vector<std::vector<double>> out(static_cast<std::size_t>(ranks_.size));
  double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
  for (std::size_t i = 0; i < mine.size(); ++i) {
    const double* x = mine.point(i);
    zmin = std::min(zmin, x[n - 1]);
    zmax = std::max(zmax, x[n - 1]);
    std::vector<double>& o = out[static_cast<std::size_t>(ranks_.rank_of_slab(bucket_of(x[n - 1])))];
    o.push_back(tag_of(my_first + i));
    o.insert(o.end(), x, x + n);
  }
  double extremes[2] = {zmin, -zmax}, global[2];
  MPI_Allreduce(extremes, global, 2, MPI_DOUBLE, MPI_MIN, ranks_.comm);
  zmin_ = global[0];
  zmax_ = -global[1];
  owned_ = all_to_all(ranks_.comm, out);
}

double OwnedPoints::edge(int s) const {
  return domain_.lo + domain_.side * static_cast<double>(s) / static_cast<double>(ranks_.slabs);
}

bool OwnedPoints::in_reach(int r, double z, double h) const {
  const int s0 = ranks_.first_slab(r), s1 = ranks_.first_slab(r + 1);
  if (s0 == s1) return false;  // a rank without slabs owns no point: it needs no halo
  // The same bounds as the receiving rank's margins (nearest_distances: range_lo - h, range_hi + h).
  const double lo = edge(s0) - h, hi = edge(s1) + h;
  if (z >= lo && z < hi) return true;
  if (!periodic_) return false;
  const double side = domain_.side;
  return hi - lo >= side || (z + side >= lo && z + side < hi) || (z - side >= lo && z - side < hi);
}

std::vector<double> OwnedPoints::halo(double h) const {
  // Each owned point to every other rank whose widened range holds it (O(P) tests a point: the ranks are
  // few beside the points).
  const std::size_t record = static_cast<std::size_t>(n_) + 1;
  std::vector<std::vector<double>> out(static_cast<std::size_t>(ranks_.size));
  for (std::size_t k = 0; k < owned_.size(); k += record)
    for (int r = 0; r < ranks_.size; ++r)
      if (r != ranks_.rank && in_reach(r, owned_[k + static_cast<std::size_t>(n_)], h))
        out[static_cast<std::size_t>(r)].insert(out[static_cast<std::size_t>(r)].end(), owned_.begin() + static_cast<std::ptrdiff_t>(k),
                                                owned_.begin() + static_cast<std::ptrdiff_t>(k + record));
  return all_to_all(ranks_.comm, out);
}

std::vector<std::pair<std::uint64_t, double>> OwnedPoints::nearest_distances(const std::vector<std::uint64_t>& first_rows,
                                                                             std::uint64_t total, KnnBackend knn,
                                                                             int threads,
                                                                             const FractionProgress& progress) {
  const int n = n_;
  const std::size_t record = static_cast<std::size_t>(n) + 1;
  const double side = domain_.side;
  const std::vector<double>& owned = owned_;
  const std::uint64_t queries = owned.size() / record;
  const double range_lo = edge(ranks_.first_slab(ranks_.rank)), range_hi = edge(ranks_.first_slab(ranks_.rank + 1));
  // d: each owned point's distance; pending: the points whose distance is not yet known to be exact.
  std::vector<double> d(queries, std::numeric_limits<double>::quiet_NaN());
  std::vector<std::uint64_t> pending(queries);
  for (std::uint64_t q = 0; q < queries; ++q) pending[q] = q;
  double h = side / std::pow(static_cast<double>(total), 1.0 / n);
  for (int attempt = 0;; ++attempt) {
    const std::vector<double> halo_points = halo(h);
    // The loaded region [lo, hi) in the last coordinate; on the torus (also a side away) it may wrap
    // around whole, and then every point is loaded and nothing lies beyond it.
    const double lo = range_lo - h, hi = range_hi + h;
    const bool wraps_whole = periodic_ && hi - lo >= side;
    const bool all_below = wraps_whole || (!periodic_ && lo <= zmin_);
    const bool all_above = wraps_whole || (!periodic_ && hi > zmax_);
    double needed = h;
    std::vector<std::uint64_t> still;
    if (!pending.empty()) {
      // The set: the pending points first, then every other loaded point (first attempt) or those within
      // the windows [z - d, z + d] of the pending points' last distances d (later attempts: a pending
      // point's nearest neighbour is no farther than the point found before, which is still loaded, so
      // it lies in its window, on the torus possibly a side away; only the few points near the range's
      // edges are measured again).
      std::vector<IntervalUnion::Interval> reaches;
      if (attempt > 0) {
        for (std::uint64_t q : pending) {
          const double z = owned[q * record + n], reach = d[q] * (1.0 + 1e-6) + 1e-9 * side;
          reaches.emplace_back(std::isfinite(reach) ? z - reach : -std::numeric_limits<double>::infinity(),
                               std::isfinite(reach) ? z + reach : std::numeric_limits<double>::infinity());
        }
      }
      const IntervalUnion windows(std::move(reaches));
      const auto in_windows = [&](double z) {
        if (attempt == 0) return true;
        return windows.contains(z) || (periodic_ && (windows.contains(z + side) || windows.contains(z - side)));
      };
      PointSet set{n, {}, domain_};
      std::vector<char> is_pending(queries, 0);
      const auto add = [&](const double* r) { set.coordinates.insert(set.coordinates.end(), r + 1, r + record); };
      for (std::uint64_t q : pending) {
        is_pending[q] = 1;
        add(owned.data() + q * record);
      }
      for (std::uint64_t q = 0; q < queries; ++q)
        if (!is_pending[q] && in_windows(owned[q * record + n])) add(owned.data() + q * record);
      for (std::size_t k = 0; k < halo_points.size(); k += record)
        if (in_windows(halo_points[k + static_cast<std::size_t>(n)])) add(halo_points.data() + k);
      if (set.size() < 2) {
        if (all_below && all_above) throw std::invalid_argument("the statistics need at least 2 points");
        needed = 2.0 * h;
        still = pending;
      } else {
        // Few pending points (later attempts): each against every point of the set, by distance_between
        // (periodic_distance_between on the torus), the functions through which the KD-trees report their
        // distances too (the same bits); else the KD-tree over the whole set, as one process measures, with
        // only the pending points queried (the halo's distances were thrown away).
        std::vector<double> found;
        if (static_cast<double>(pending.size()) * static_cast<double>(set.size()) <= 5e7) {
          found.assign(pending.size(), std::numeric_limits<double>::infinity());
          for (std::size_t j = 0; j < pending.size(); ++j)
            for (std::size_t k = 0; k < set.size(); ++k)
              if (k != j)
                found[j] = std::min(found[j], periodic_ ? periodic_distance_between(set, j, k) : distance_between(set, j, k));
        } else {
          const FractionProgress report = attempt == 0 ? progress : FractionProgress{};
          // The tree over the whole set, queried for the pending points only (the set's first rows).
          found = periodic_ ? periodic_nearest_neighbour_distances_of_first(set, pending.size(), threads, report)
                            : nearest_neighbour_distances_of_first(set, pending.size(), knn, threads, report);
        }
        // The one-process stream's rule (streamed_sampling.cpp, measure_bucket): a point outside [lo, hi)
        // (and, on the torus, its images) is at least the margin from the query in its last coordinate.
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
    MPI_Allreduce(&needed, &most, 1, MPI_DOUBLE, MPI_MAX, ranks_.comm);
    if (most <= h) break;
    h = attempt < 4 ? most : 2.0 * h;
  }
  // Each distance back to the rank that made its point.
  std::vector<std::vector<double>> back(static_cast<std::size_t>(ranks_.size));
  for (std::uint64_t q = 0; q < queries; ++q) {
    const std::uint64_t index = index_of(owned[q * record]);
    const int r = static_cast<int>(std::upper_bound(first_rows.begin(), first_rows.end(), index) - first_rows.begin()) - 1;
    back[static_cast<std::size_t>(r)].push_back(owned[q * record]);
    back[static_cast<std::size_t>(r)].push_back(d[q]);
  }
  const std::vector<double> in = all_to_all(ranks_.comm, back);
  std::vector<std::pair<std::uint64_t, double>> pairs(in.size() / 2);
  for (std::size_t k = 0; k < pairs.size(); ++k) pairs[k] = {index_of(in[2 * k]), in[2 * k + 1]};
  std::sort(pairs.begin(), pairs.end());
  const std::uint64_t my_first = first_rows[static_cast<std::size_t>(ranks_.rank)];
  if (pairs.size() != first_rows[static_cast<std::size_t>(ranks_.rank) + 1] - my_first)
    throw std::logic_error("a point without its nearest-neighbour distance");
  for (std::size_t k = 0; k < pairs.size(); ++k)
    if (pairs[k].first != my_first + k) throw std::logic_error("a point without its nearest-neighbour distance");
  return pairs;
}

RdfCurve OwnedPoints::radial_distribution(const RdfOptions& options, std::uint64_t seed, std::uint64_t total,
                                          int threads, const FractionProgress& progress) {
  const RdfPlan plan = plan_radial_distribution(n_, domain_, total, options);
  const RdfQueries is_query(options, seed, total);
  // The halo holds every point within r_max of this rank's points (sample --stream's RDF halo).
  const std::vector<double> near = halo(plan.r_max * (1.0 + 1e-6) + 1e-9 * domain_.side);
  const std::size_t record = static_cast<std::size_t>(n_) + 1;
  const std::uint64_t owned = owned_.size() / record, count = owned + near.size() / record;
  int too_many = count > std::numeric_limits<std::uint32_t>::max(), any = 0;
  MPI_Allreduce(&too_many, &any, 1, MPI_INT, MPI_MAX, ranks_.comm);
  if (any)
    throw std::invalid_argument("a rank's points with their RDF halo number more than 2^32: run on more ranks (or raise --slabs)");
  PointSet set{n_, {}, domain_};
  set.coordinates.reserve(count * static_cast<std::uint64_t>(n_));
  const auto add = [&](const std::vector<double>& records) {
    for (std::size_t k = 0; k < records.size(); k += record)
      set.coordinates.insert(set.coordinates.end(), records.begin() + static_cast<std::ptrdiff_t>(k + 1),
                             records.begin() + static_cast<std::ptrdiff_t>(k + record));
  };
  add(owned_);
  add(near);
  std::vector<std::uint32_t> rows;
  for (std::uint64_t q = 0; q < owned; ++q)
    if (is_query(index_of(owned_[q * record]))) rows.push_back(static_cast<std::uint32_t>(q));
  RdfPairSums sums = plan.empty_sums();
  if (!rows.empty()) count_rdf_pairs(set, rows, plan, sums, threads, progress);
  reduce_rdf_pair_sums(ranks_.comm, sums);
  unsigned long long mine = rows.size(), queries = 0;
  MPI_Allreduce(&mine, &queries, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, ranks_.comm);
  return finish_radial_distribution(plan, sums, queries);
}

}  // namespace dfvn
