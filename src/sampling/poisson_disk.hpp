// Poisson disk sampling by dart throwing from an active list (Bridson 2007, "Fast Poisson disk
// sampling in arbitrary dimensions"), with a minimum-distance guarantee in every dimension.
#pragma once

#include <cstdint>
#include <limits>

#include "core/progress.hpp"
#include "sampling/point_set.hpp"

namespace dfvn {

struct PoissonDiskOptions {
  double radius = 0.1;     // no two points closer than this
  int candidates = 30;     // Bridson's k: attempts around an active point before it retires
  std::uint64_t max_points = std::numeric_limits<std::uint64_t>::max();  // stop once this many are placed
  Box domain;

  void validate(int dimension) const;  // throws std::invalid_argument naming the option
};

struct PoissonDiskResult {
  PointSet points;
  std::uint64_t candidates_tried = 0;
  bool reached_max_points = false;  // false: the active list emptied first (the set is saturated)
};

// Bridson's algorithm: start from one uniform point; repeatedly pick a random active point and try
// up to k candidates uniform in the volume of the annulus [r, 2r] around it; the first candidate that
// lies in the domain and at distance >= r from every point is accepted and becomes active; a point
// whose k candidates all fail retires.
//
// Conflicts are found with a hashed grid of cells of side r: only occupied cells are stored (memory
// O(points), never a dense (sqrt(N)/r)^N array), and a candidate visits only the neighbouring cells
// (offsets -1, 0, +1 per axis) whose box comes closer than r, pruned axis by axis. Every point that
// could be closer than r is compared by its exact distance, so the guarantee holds in every dimension
// (SciPy 1.10's grid of side r/sqrt(N) checks only +-2 cells, which misses conflicts for N >= 5).
// Deterministic per seed: all randomness is keyed by (seed, candidate counter). `progress`: points
// placed over max_points (a saturated set stops short of 1).
template <int N>
PoissonDiskResult poisson_disk(const PoissonDiskOptions& options, std::uint64_t seed, const FractionProgress& progress = {});

PoissonDiskResult poisson_disk(int dimension, const PoissonDiskOptions& options, std::uint64_t seed,
                               const FractionProgress& progress = {});

}  // namespace dfvn
