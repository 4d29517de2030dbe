// The grid search of minimum-image nearest neighbours (stats/cell_grid_neighbours.hpp): the same bits as the
// KD-tree search and as brute force, in every build and for any thread count, and declining the sets it
// would be slow for.
#include "dfvn/stats/cell_grid_neighbours.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "dfvn/core/dimension.hpp"
#include "dfvn/sampling/jitter.hpp"
#include "dfvn/stats/nearest_other.hpp"
#include "dfvn/stats/periodic_neighbours.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

// The nearest minimum-image distances of the points `which` by brute force.
std::vector<double> brute_force_of(const PointSet& p, const std::vector<std::size_t>& which) {
  std::vector<double> best(which.size(), std::numeric_limits<double>::infinity());
  for (std::size_t w = 0; w < which.size(); ++w)
    for (std::size_t j = 0; j < p.size(); ++j)
      if (j != which[w]) best[w] = std::min(best[w], periodic_distance_between(p, which[w], j));
  return best;
}

// The KD-tree search (the widest build), every point.
template <int N>
std::vector<double> kd_tree(const PointSet& p) {
  return nearest_other::nearest_distances<N, true>(p, p.size(), 1, {}, nearest_other::periodic_torus(p.domain.lo, p.domain.side),
                                                   [&](std::size_t i, std::size_t j) { return periodic_distance_between(p, i, j); });
}

// Adds duplicates, a point on each face of axis 0 and points a hair inside both faces.
void add_hard_points(PointSet& p) {
  const int n = p.dimension;
  const Box box{p.domain.lo, p.domain.side};
  for (int k = 0; k < 3; ++k) p.coordinates.insert(p.coordinates.end(), p.point(k * 5), p.point(k * 5) + n);
  for (const double x0 : {box.lo, box.lo + box.side, std::nextafter(box.lo, 1e9), std::nextafter(box.lo + box.side, -1e9)}) {
    std::vector<double> x(n, box.lo + 0.37 * box.side);
    x[0] = x0;
    x[n - 1] = x0;  // the line axis too
    p.coordinates.insert(p.coordinates.end(), x.begin(), x.end());
  }
}

// 4D-8D: uniform random sets with the hard points and cell-centred lattices (exact ties, across the faces
// too), in a box that does not start at 0 and in one far from the origin, with about 1-1.5 points per cell:
// the grid (both builds, 1 and 2 threads) equals the KD-tree search (4D-7D) and brute force (207 points,
// 4D-8D) to the bit.
TEST(CellGridNeighbours, EqualsKdTreeAndBruteForce) {
  for (const Box box : {Box{-2.0, 3.0}, Box{1000.25, 0.75}})
    for (int dimension = 4; dimension <= 8; ++dimension) {
      // 8D (at least 4^8 points) once, without the lattice and the baseline build: the test's time.
      if (dimension == 8 && box.lo != -2.0) continue;
      const std::size_t count = static_cast<std::size_t>(std::pow(4.0, dimension)) * (dimension == 8 ? 2 : 3) / 2 + 100;
      PointSet random = uniform_random_points(dimension, count, box, 300 + static_cast<std::uint64_t>(dimension), 2);
      add_hard_points(random);
      const int side = dimension == 4 ? 7 : dimension == 5 ? 5 : 4;
      PointSet lattice = testing::fair_lattice_in(dimension, side, box);
      dispatch_dimension(dimension, [&]<int N>() {
        for (const PointSet* p : {&random, &lattice}) {
          if (N == 8 && p == &lattice) continue;
          const std::string what = std::to_string(N) + "D " + (p == &random ? "random" : "lattice") + " in [" + std::to_string(box.lo) + ", +" + std::to_string(box.side) + "]";
          const auto grid = cell_grid::periodic_nearest_distances(*p, p->size(), 2, {});
          ASSERT_TRUE(grid.has_value()) << what;
          if (N < 8) {
            const auto baseline = cell_grid::periodic_nearest_distances(*p, p->size(), 1, {}, Simd::baseline);
            ASSERT_TRUE(baseline.has_value()) << what;
            EXPECT_EQ(*baseline, *grid) << what << ": the baseline build on one thread";
          }
          if (N <= 7) EXPECT_EQ(*grid, kd_tree<N>(*p)) << what << ": the KD-tree search";
          // Brute force for the first 200 points and the last 7 (the random set's hard points: duplicates at 0,
          // the two faces of axis 0 and of the line axis meet).
          std::vector<std::size_t> which;
          for (std::size_t i = 0; i < 200; ++i) which.push_back(i);
          for (std::size_t i = p->size() - 7; i < p->size(); ++i) which.push_back(i);
          const std::vector<double> brute = brute_force_of(*p, which);
          for (std::size_t w = 0; w < which.size(); ++w) EXPECT_EQ((*grid)[which[w]], brute[w]) << what << " point " << which[w];
          // Only the first points queried: the same values.
          const auto some = cell_grid::periodic_nearest_distances(*p, p->size() / 3, 2, {});
          ASSERT_TRUE(some.has_value());
          EXPECT_EQ(*some, std::vector<double>(grid->begin(), grid->begin() + static_cast<std::ptrdiff_t>(p->size() / 3))) << what;
        }
      });
    }
}

// It declines what it would be slow for (the KD-tree search then answers, as the periodic statistics' tests
// check): 2D and 3D, fewer than 4 cells per axis, a set crowded into a corner of its torus; and the periodic
// statistics give the KD-tree's answer for such a set.
TEST(CellGridNeighbours, DeclinesSetsItWouldBeSlowFor) {
  EXPECT_FALSE(cell_grid::periodic_nearest_distances(uniform_random_points(3, 50000, Box{0.0, 1.0}, 1, 1), 50000, 1, {}));
  EXPECT_FALSE(cell_grid::periodic_nearest_distances(uniform_random_points(5, 1000, Box{0.0, 1.0}, 1, 1), 1000, 1, {}));
  EXPECT_TRUE(cell_grid::periodic_nearest_distances(uniform_random_points(5, 1024, Box{0.0, 1.0}, 1, 1), 1024, 1, {}));
  PointSet corner = uniform_random_points(5, 4000, Box{0.0, 0.3}, 2, 1);
  corner.domain = Box{0.0, 1.0};
  EXPECT_FALSE(cell_grid::periodic_nearest_distances(corner, corner.size(), 1, {}));
  EXPECT_EQ(periodic_nearest_neighbour_distances(corner, 2), kd_tree<5>(corner));
}

}  // namespace
}  // namespace dfvn
