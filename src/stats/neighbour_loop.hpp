// The loops that the Euclidean and the periodic nearest-neighbour distances share (private to stats/,
// not installed): one query per point in parallel, with progress, and the O(n^2) brute force that the
// tests compare them with.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <limits>
#include <vector>

#include "dfvn/core/parallel.hpp"
#include "dfvn/core/progress.hpp"

namespace dfvn::neighbour_loop {

// distances[original[k]] = nearest(k) for every row k of a LeafOrderedTree (stats/kd_tree.hpp) whose input
// point is one of the first `queries` (original[k] < queries; the result has `queries` slots), in chunks
// of consecutive rows on a dynamic schedule: the queries go in the tree's leaf order and the results are
// scattered back to the input's indices. Rows done are counted per chunk, and only the first thread
// reports them. Each slot is written by one query, so the result is the same for any thread count and any
// order.
template <typename Nearest>
std::vector<double> for_every_point(const std::vector<std::uint32_t>& original, std::size_t queries, int threads,
                                    const FractionProgress& progress, Nearest nearest) {
  const auto count = static_cast<std::int64_t>(original.size());
  std::vector<double> distances(queries);
  constexpr std::int64_t kChunk = 4096;
  std::atomic<std::uint64_t> queries_done{0};
#pragma omp parallel for schedule(dynamic, kChunk) num_threads(resolve_threads(threads))
  for (std::int64_t k = 0; k < count; ++k) {
    if (progress && k % kChunk == 0) {
      const std::uint64_t done = queries_done.fetch_add(static_cast<std::uint64_t>(kChunk), std::memory_order_relaxed);
      if (omp_get_thread_num() == 0) progress(std::min(1.0, static_cast<double>(done) / static_cast<double>(count)));
    }
    const std::uint32_t self = original[static_cast<std::size_t>(k)];
    if (self < queries) distances[self] = nearest(static_cast<std::size_t>(k));
  }
  return distances;
}

// chunk(begin, end) for consecutive ranges [0, count) of 64 items (rows, leaves) on a dynamic schedule, with progress as in
// for_every_point. Each row belongs to one chunk, so the results do not depend on the thread count.
template <typename Chunk>
void for_every_chunk(std::size_t count, int threads, const FractionProgress& progress, Chunk chunk) {
  constexpr std::int64_t kChunk = 64;
  const auto chunks = (static_cast<std::int64_t>(count) + kChunk - 1) / kChunk;
  std::atomic<std::uint64_t> items_done{0};
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolve_threads(threads))
  for (std::int64_t c = 0; c < chunks; ++c) {
    const auto begin = static_cast<std::size_t>(c * kChunk);
    const std::size_t end = std::min(count, begin + static_cast<std::size_t>(kChunk));
    chunk(begin, end);
    if (progress) {
      const std::uint64_t done = items_done.fetch_add(end - begin, std::memory_order_relaxed) + (end - begin);
      if (omp_get_thread_num() == 0) progress(std::min(1.0, static_cast<double>(done) / static_cast<double>(count)));
    }
  }
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
