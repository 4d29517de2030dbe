// Poisson disk sampling by dart throwing from an active list (Bridson 2007, "Fast Poisson disk
// sampling in arbitrary dimensions"), with a minimum-distance guarantee in every dimension.
#pragma once

#include <cstdint>
#include <limits>

#include "core/progress.hpp"
#include "sampling/point_set.hpp"

namespace dfvn {

// Where the cells of side r live: a dense array of all (side / r)^N cells, or a hash table of the
// occupied ones. `automatic` takes the dense array when it needs no more memory than about four
// times the points it will hold (or at most 64 MiB), the hash table beyond. The output is the same
// for all three.
enum class PoissonDiskGrid { automatic, dense, hashed };

struct PoissonDiskOptions {
  double radius = 0.1;     // no two points closer than this
  int candidates = 30;     // Bridson's k: candidates thrown around each point before it retires
  std::uint64_t max_points = std::numeric_limits<std::uint64_t>::max();  // stop once this many are placed
  Box domain;
  PoissonDiskGrid grid = PoissonDiskGrid::automatic;

  void validate(int dimension) const;  // throws std::invalid_argument naming the option
};

struct PoissonDiskResult {
  PointSet points;
  std::uint64_t candidates_tried = 0;  // as the sequential algorithm below counts them
  bool reached_max_points = false;     // false: the active list emptied first (the set is saturated)
};

// Bridson's algorithm with the active list as a queue, as SciPy's qmc.PoissonDisk runs it but in
// first-in first-out order: start from one uniform point; take the oldest active point, throw k
// candidates uniform in the volume of the annulus [r, 2r] around it, accept every candidate that lies
// in the domain at distance >= r from every point accepted so far (in the order thrown), and retire
// the point; accepted points join the queue. It ends when the queue empties (the set is saturated:
// every point has had its k candidates) or max_points are placed. Points come out in the order accepted.
//
// Candidate t of point i is a pure function of (seed, i, t), so the process above is deterministic per
// seed; it runs in batches of queued points: their candidates are thrown and checked against the
// points of the batch's start in parallel, then the survivors are checked in order against the
// points accepted since. That is the same sequence of decisions, so the output does not depend on
// the thread count (or the batch size).
//
// Conflicts are found in a grid of cells of side r (dense or hashed, PoissonDiskGrid) whose points'
// coordinates are stored in the cell: a candidate visits only the neighbouring cells (offsets -1, 0, +1
// per axis) whose box comes closer than r, pruned axis by axis, and compares exact distances, so the
// guarantee holds in every dimension (SciPy 1.10's grid of side r/sqrt(N) checks only +-2 cells,
// which misses conflicts for N >= 5). `threads`: 0 = all cores. `progress`: points placed over
// max_points (a saturated set stops short of 1), reported from one thread.
template <int N>
PoissonDiskResult poisson_disk(const PoissonDiskOptions& options, std::uint64_t seed, int threads = 0,
                               const FractionProgress& progress = {});

PoissonDiskResult poisson_disk(int dimension, const PoissonDiskOptions& options, std::uint64_t seed, int threads = 0,
                               const FractionProgress& progress = {});

}  // namespace dfvn
