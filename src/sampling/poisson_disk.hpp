// Poisson disk sampling by dart throwing from an active list (Bridson 2007, "Fast Poisson disk
// sampling in arbitrary dimensions"), with a minimum-distance guarantee in every dimension.
#pragma once

#include <cstdint>
#include <limits>

#include "dfvn/core/progress.hpp"
#include "dfvn/core/point_set.hpp"

namespace dfvn {

// Where the cells of side r live: a dense array of all (side / r)^N cells, or a hash table of the
// occupied ones (room for min(max_points, cells) of them). `automatic` takes the dense array when it
// costs at most 8x the coordinates of the points it may hold (plus 16 bytes each), or 64 MiB, the
// hash table beyond: in practice only a max_points far below the cell count gets the table. The
// output is the same for all three.
enum class PoissonDiskGrid { automatic, dense, hashed };

struct PoissonDiskOptions {
  double radius = 0.1;     // no two points closer than this (on the torus: in its minimum-image metric)
  int candidates = 30;     // Bridson's k: candidates thrown per visit of a point
  std::uint64_t max_points = std::numeric_limits<std::uint64_t>::max();  // stop once this many are placed
  // The cube, the torus (candidates wrap around it and distances are minimum-image ones, as UTK's
  // toroidal Bridson sampler; the radius at most half the side) or the ball inscribed in the cube.
  Domain domain;
  PoissonDiskGrid grid = PoissonDiskGrid::automatic;

  void validate(int dimension) const;  // throws std::invalid_argument naming the option
};

struct PoissonDiskResult {
  PointSet points;
  std::uint64_t candidates_tried = 0;  // k per visit, up to the candidate that placed the last point
  bool reached_max_points = false;     // false: the active list emptied first (the set is saturated)
  double radius = 0.0;                 // the radius of the run (poisson_disk_reaching: the one it found)
  int runs = 1;                        // poisson_disk_reaching: the processes it ran
};

// Bridson's algorithm with the active list as a first-in first-out queue of visits. Start from one
// uniform point. A visit throws k candidates uniform in the volume of the annulus [r, 2r] around its
// point and places every candidate that lies in the domain at distance >= r from every point placed
// so far, in the order thrown (as SciPy's qmc.PoissonDisk does); placed points join the queue, and so
// does the visited point again if its visit placed any, else it retires (Bridson's rule: a retired
// point's last k candidates all failed). It ends when the queue empties (the set is saturated) or
// max_points are placed. Points come out in the order placed.
//
// Candidates keep that exact law: the ones that fall outside the domain (half of them in the 7D paper
// row) are drawn and then dropped before any grid look-up. Not drawing them at all would need the
// volume of the annulus inside the box, which has no closed form near its corners, or another law.
//
// Candidate t of visit v of point i is a pure function of (seed, i, v, t), so the process is
// deterministic per seed, and it runs on several threads without changing: one thread makes the
// decisions in queue order, while helper threads throw the candidates of later visits ahead of it and
// check them against the points placed when they began; the deciding thread checks those survivors
// only against the points placed since. The output does not depend on the thread count or timing.
//
// Conflicts are found in a grid of cells of side r (dense or hashed, PoissonDiskGrid) that holds the
// points' coordinates in their cells: a candidate visits only the cells whose box comes closer than
// r, the nearest first, and compares exact distances, so the guarantee holds in every dimension
// (SciPy 1.10's grid of side r/sqrt(N) checks only +-2 cells, which misses conflicts for N >= 5).
// `threads`: 0 = all cores. `progress`: points placed over max_points (a saturated set stops short
// of 1), reported from one thread.
template <int N>
PoissonDiskResult poisson_disk(const PoissonDiskOptions& options, std::uint64_t seed, int threads = 0,
                               const FractionProgress& progress = {});

PoissonDiskResult poisson_disk(int dimension, const PoissonDiskOptions& options, std::uint64_t seed, int threads = 0,
                               const FractionProgress& progress = {});

// The saturation density of the process above: a set that ran until its queue emptied holds about
// D_N V / r^N points in a domain of volume V at radius r (on the torus, which has no boundary, exactly
// so up to fluctuations of a few tenths of a percent). Measured for k = 30 candidates in 2D-8D; the
// measurements and the command are in data/poisson_disk_saturation.md.
double poisson_disk_saturation_density(int dimension);
// The points of a saturated set at radius r in `domain`: D V / r^N on the torus; in the cube and the ball,
// whose faces hold more, times (1 + B (2N / side) r) with the boundary term B measured alike (the same
// record).
double poisson_disk_saturation_points(int dimension, const Domain& domain, double radius);

// Poisson disk points at the largest radius the process reaches options.max_points with (options.radius
// is ignored): the first run takes the radius at which the saturation density above gives max_points,
// less kReachingMargin (from poisson_disk_saturation_points); a run whose queue empties first with m
// points is followed by one at its radius times (m / max_points)^(1/N), less the margin, until one
// reaches the count (at most kMaxReachingRuns). The result is that last run, at one radius throughout,
// with the radius and the runs it took: a process at r / (1 - kReachingMargin) would saturate short of
// the count (within the tables' fluctuations, data/poisson_disk_saturation.md). Throws
// std::runtime_error when no run within kMaxReachingRuns reaches the count.
inline constexpr double kReachingMargin = 0.002;
inline constexpr int kMaxReachingRuns = 8;
PoissonDiskResult poisson_disk_reaching(int dimension, const PoissonDiskOptions& options, std::uint64_t seed,
                                        int threads = 0, const FractionProgress& progress = {});

}  // namespace dfvn
