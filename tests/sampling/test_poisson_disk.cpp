#include "sampling/poisson_disk.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "stats/nearest_neighbour.hpp"

namespace dfvn {
namespace {

// The minimum-distance guarantee, checked by brute force over all pairs, in 5D-7D (where SciPy 1.10's
// PoissonDisk breaks it). The boxes are sized to a few thousand to ~16,000 points each.
class PoissonDiskGuarantee : public ::testing::TestWithParam<std::pair<int, double>> {};

TEST_P(PoissonDiskGuarantee, NoTwoPointsCloserThanTheRadius) {
  const auto [dimension, side] = GetParam();
  PoissonDiskOptions o;
  o.radius = 0.1;
  o.domain = Box{0.0, side};
  const std::uint64_t seed = 31 + static_cast<std::uint64_t>(dimension);
  const PoissonDiskResult r = poisson_disk(dimension, o, seed);
  ASSERT_GT(r.points.size(), 1000u);
  EXPECT_FALSE(r.reached_max_points);
  const auto nearest = nearest_neighbour_distances_brute_force(r.points);
  const double min = *std::min_element(nearest.begin(), nearest.end());
  std::printf("%dD [0,%.2f]^%d: %zu points, min distance %.9f (seed %llu)\n", dimension, side, dimension,
              r.points.size(), min, static_cast<unsigned long long>(seed));
  EXPECT_GE(min, o.radius);
  for (std::size_t i = 0; i < r.points.size(); ++i) EXPECT_TRUE(o.domain.contains(r.points.point(i), dimension));
}

INSTANTIATE_TEST_SUITE_P(HighDimensions, PoissonDiskGuarantee,
                         ::testing::Values(std::make_pair(3, 2.0), std::make_pair(5, 0.6), std::make_pair(6, 0.5),
                                           std::make_pair(7, 0.4)));

TEST(PoissonDisk, DeterministicPerSeedAndStopsAtMaxPoints) {
  PoissonDiskOptions o;
  o.radius = 0.05;
  o.max_points = 500;
  const auto a = poisson_disk(4, o, 5), b = poisson_disk(4, o, 5), c = poisson_disk(4, o, 6);
  EXPECT_EQ(a.points.coordinates, b.points.coordinates);
  EXPECT_NE(a.points.coordinates, c.points.coordinates);
  EXPECT_EQ(a.points.size(), 500u);
  EXPECT_TRUE(a.reached_max_points);
}

TEST(PoissonDisk, FillsTheDomainDenselyEnough) {
  // Bridson's sets are near-saturated: in 2D with r = 0.05 on the unit square, random sequential
  // packing reaches ~0.547 coverage by disks of radius r/2, i.e. ~280 points; dart throwing from an
  // active list with k = 30 gets close to that.
  PoissonDiskOptions o;
  o.radius = 0.05;
  const auto r = poisson_disk(2, o, 3);
  EXPECT_GT(r.points.size(), 230u);
  EXPECT_LT(r.points.size(), 340u);
}

TEST(PoissonDisk, RejectsBadOptions) {
  PoissonDiskOptions o;
  o.radius = 0.0;
  EXPECT_THROW(o.validate(3), std::invalid_argument);
  o.radius = 1e-9;  // 1e9 cells per axis do not pack into 64 bits in 8D
  EXPECT_THROW(o.validate(8), std::invalid_argument);
  o.radius = 0.1;
  o.candidates = 0;
  EXPECT_THROW(o.validate(3), std::invalid_argument);
}

}  // namespace
}  // namespace dfvn
