// The loops that the Euclidean and the periodic nearest-neighbour distances share (private to stats/,
// not installed): chunks of leaves in parallel, with progress, and the O(n^2) brute force that the tests
// compare them with.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <limits>
#include <vector>

#include "dfvn/core/parallel.hpp"
#include "dfvn/core/progress.hpp"

namespace dfvn::neighbour_loop {

// The searches' relative pruning margin: a subtree, leaf or cell is skipped only when its lower bound
// exceeds the best squared distance by this much, far above the bound's rounding (a few units in the last
// place), so that no closer point is ever pruned (stats/nearest_other.hpp, stats/cell_grid_neighbours.cpp).
inline constexpr double kPruneMargin = 1.0 + 1e-9;

// chunk(begin, end) for consecutive ranges [0, count) of 64 items (rows, leaves) on a dynamic schedule. Items done are
// counted per chunk, and only the first thread reports them. Each item belongs to one chunk, so the results do not
// depend on the thread count.
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
