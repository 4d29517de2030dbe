#include "dfvn/stats/nearest_neighbour.hpp"

#include <gtest/gtest.h>

#include "dfvn/sampling/jitter.hpp"
#include "dfvn/sampling/poisson_disk.hpp"

namespace dfvn {
namespace {

// nanoflann = FLANN = brute force, to the last bit, in 2D-8D, including a set with duplicates.
TEST(NearestNeighbour, KdTreesEqualBruteForce) {
  for (int dimension = 2; dimension <= 8; ++dimension) {
    PointSet p = uniform_random_points(dimension, 3000, Box{0.0, 1.0}, 100 + dimension, 2);
    // Duplicate a few points: their nearest distance is 0.
    for (int k = 0; k < 5; ++k)
      p.coordinates.insert(p.coordinates.end(), p.point(k * 7), p.point(k * 7) + dimension);
    const auto brute = nearest_neighbour_distances_brute_force(p);
    const auto nano = nearest_neighbour_distances(p, KnnBackend::nanoflann, 2);
    const auto flann = nearest_neighbour_distances(p, KnnBackend::flann, 2);
    ASSERT_EQ(nano.size(), brute.size());
    for (std::size_t i = 0; i < brute.size(); ++i) {
      EXPECT_EQ(nano[i], brute[i]) << dimension << "D point " << i;
      EXPECT_EQ(flann[i], brute[i]) << dimension << "D point " << i;
    }
    EXPECT_EQ(nano[0], 0.0);
  }
}

TEST(NearestNeighbour, SummaryOfALattice) {
  // A cell-centred 10^3 lattice: every nearest distance is the spacing 0.1, scaled median 1.
  const LatticeSpec l{3, 10, Protocol::unit};
  PointSet p{3, Coordinates(3000, 0.0), Box{0.0, 1.0}};
  for (std::uint64_t i = 0; i < 1000; ++i) l.point(i, p.coordinates.data() + 3 * i);
  const auto s = summarize_nearest_neighbours(nearest_neighbour_distances(p, KnnBackend::nanoflann, 1), p);
  EXPECT_EQ(s.points, 1000u);
  EXPECT_NEAR(s.min, 0.1, 1e-12);
  EXPECT_NEAR(s.median, 0.1, 1e-12);
  EXPECT_NEAR(s.median_scaled, 1.0, 1e-12);
}

TEST(NearestNeighbour, MedianOfEvenCountAveragesTheMiddle) {
  PointSet p{1, {0.0, 1.0}, Box{0.0, 1.0}};
  const auto s = summarize_nearest_neighbours({1.0, 2.0, 4.0, 3.0}, p);
  EXPECT_DOUBLE_EQ(s.median, 2.5);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.min, 1.0);
}

TEST(NearestNeighbour, IndependentOfThreads) {
  const PointSet p = uniform_random_points(6, 20000, Box{0.0, 1.0}, 8, 2);
  EXPECT_EQ(nearest_neighbour_distances(p, KnnBackend::nanoflann, 1), nearest_neighbour_distances(p, KnnBackend::nanoflann, 2));
  EXPECT_EQ(nearest_neighbour_distances(p, KnnBackend::flann, 1), nearest_neighbour_distances(p, KnnBackend::flann, 2));
}

}  // namespace
}  // namespace dfvn
