// The loops that the Euclidean and the periodic nearest-neighbour distances share (private to stats/,
// not installed): one query per point in parallel, with progress, and the O(n^2) brute force that the
// tests compare them with.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/parallel.hpp"
#include "core/progress.hpp"

namespace dfvn::neighbour_loop {

// distances[i] = nearest(i) for every i < count, in chunks of a dynamic schedule; queries done are
// counted per chunk, and only the first thread reports them. Each slot is written by one query, so the
// result is the same for any thread count and any order.
//
// The points are queried in `order` (a permutation of 0..count-1): a KD-tree's leaf order (tree_order),
// so that consecutive queries walk the same nodes and leaves and find them in cache. For point sets in
// no spatial order (Sobol, Poisson disk) this is 2-3x faster than querying by index
// (bench/results.md); the distances are the same bits.
template <typename Nearest>
std::vector<double> for_every_point(const std::vector<std::uint32_t>& order, int threads, const FractionProgress& progress,
                                    Nearest nearest) {
  const auto count = static_cast<std::int64_t>(order.size());
  std::vector<double> distances(static_cast<std::size_t>(count));
  constexpr std::int64_t kChunk = 4096;
  std::atomic<std::uint64_t> queries_done{0};
#pragma omp parallel for schedule(dynamic, kChunk) num_threads(resolve_threads(threads))
  for (std::int64_t k = 0; k < count; ++k) {
    if (progress && k % kChunk == 0) {
      const std::uint64_t done = queries_done.fetch_add(static_cast<std::uint64_t>(kChunk), std::memory_order_relaxed);
      if (omp_get_thread_num() == 0) progress(std::min(1.0, static_cast<double>(done) / static_cast<double>(count)));
    }
    const std::size_t i = order[static_cast<std::size_t>(k)];
    distances[i] = nearest(i);
  }
  return distances;
}

// The points in the order of the tree's leaves (nanoflann keeps it in vAcc after buildIndex).
template <typename Tree>
const std::vector<std::uint32_t>& tree_order(const Tree& tree) {
  return tree.vAcc;
}

// Every pair once: distance(i, k) for i < k.
template <typename Distance>
std::vector<double> brute_force(std::size_t count, Distance distance) {
  std::vector<double> best(count, std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t k = i + 1; k < count; ++k) {
      const double d = distance(i, k);
      best[i] = std::min(best[i], d);
      best[k] = std::min(best[k], d);
    }
  return best;
}

}  // namespace dfvn::neighbour_loop
