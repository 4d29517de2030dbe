// Thread-count handling. Results never depend on the count: parallel loops write to slots indexed by
// point, and randomness is keyed by point index (core/hash.hpp).
#pragma once

#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include <fmt/format.h>

namespace dfvn {

inline int core_count() { return std::max(1, omp_get_num_procs()); }

// More threads than cores only add overhead, and libgomp crashes (stack overflow) or fails to
// allocate at about 10^5 threads. So at most 4 x the cores, and never more than kMaxThreads.
inline constexpr int kMaxThreads = 1024;
inline int max_thread_count() { return std::min(kMaxThreads, 4 * core_count()); }

// Throws std::invalid_argument unless `requested` is 0 (all cores) or 1..max_thread_count().
inline void check_thread_count(int requested) {
  if (requested < 0 || requested > max_thread_count())
    throw std::invalid_argument(fmt::format("thread count must be 0 (all cores) or 1..{} (4 x the {} cores, at most {}), "
                                            "got {}",
                                            max_thread_count(), core_count(), kMaxThreads, requested));
}

// Below about 2^20 coordinates of cheap per-coordinate work (a few milliseconds on one core) a second
// thread saves less than it can cost on a shared machine: the first parallel region of a process took
// 0.8-10 ms here (an empty region in a ten-line program), and 8192 4D Sobol points took 0.8 ms on one
// thread and 8-17 ms on two while the other core was busy. Generators pass this as the `if` clause of
// their parallel loop; the output never depends on it.
inline constexpr std::uint64_t kParallelFromCoordinates = std::uint64_t{1} << 20;
inline bool worth_threads(std::uint64_t coordinates) { return coordinates >= kParallelFromCoordinates; }

// 0 means "all available cores" (OMP_NUM_THREADS if set). Configurations call check_thread_count
// first; the clamp keeps an environment variable within the same bound.
inline int resolve_threads(int requested) {
  return std::clamp(requested > 0 ? requested : omp_get_max_threads(), 1, max_thread_count());
}

}  // namespace dfvn
