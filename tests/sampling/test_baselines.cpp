// Defining properties of the baselines a user would pick instead of CNJ: Halton and Latin hypercube.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "dfvn/core/parallel.hpp"
#include "dfvn/sampling/halton.hpp"
#include "dfvn/sampling/latin_hypercube.hpp"

namespace dfvn {
namespace {

// The first values of the van der Corput sequences in bases 2 and 3 (Halton 1960; e.g. the tables in
// Niederreiter 1992, Section 3.1): index 1, 2, 3, ... -> 1/2, 1/4, 3/4, 1/8, 5/8, ...
TEST(Halton, UnscrambledPointsArePublishedRadicalInverses) {
  const std::vector<double> base2 = {0.0, 1.0 / 2, 1.0 / 4, 3.0 / 4, 1.0 / 8, 5.0 / 8, 3.0 / 8, 7.0 / 8, 1.0 / 16};
  const std::vector<double> base3 = {0.0, 1.0 / 3, 2.0 / 3, 1.0 / 9, 4.0 / 9, 7.0 / 9, 2.0 / 9, 5.0 / 9, 8.0 / 9};
  const PointSet points = halton_points(3, base2.size(), Box{0.0, 1.0}, false, 0, 2);
  for (std::size_t i = 0; i < base2.size(); ++i) {
    EXPECT_DOUBLE_EQ(points.point(i)[0], base2[i]) << i;
    EXPECT_DOUBLE_EQ(points.point(i)[1], base3[i]) << i;
  }
  // Base 5, index 7 = (12)_5 -> 0.21_5 = 2/5 + 1/25.
  EXPECT_DOUBLE_EQ(points.point(7)[2], 2.0 / 5 + 1.0 / 25);
  EXPECT_DOUBLE_EQ(radical_inverse(1000, 7), radical_inverse(1000, 7));
  EXPECT_NEAR(radical_inverse(1000, 7), 6.0 / 7 + 2.0 / 49 + 6.0 / 343 + 2.0 / 2401, 1e-15);  // 1000 = (2626)_7
}

// Digit permutations keep Halton's stratification: the first b^m points fall one in each interval
// [j / b^m, (j + 1) / b^m) of axis k (base b).
TEST(Halton, ScrambledPointsKeepTheirStrata) {
  for (std::uint64_t seed : {1u, 2u, 99u}) {
    SCOPED_TRACE(seed);
    const PointSet points = halton_points(8, 625, Box{0.0, 1.0}, true, seed, 3);
    for (int axis = 0; axis < 8; ++axis) {
      const int base = halton_base(axis);
      std::uint64_t strata = 1;
      while (strata * base <= points.size()) strata *= static_cast<std::uint64_t>(base);
      std::vector<int> hits(strata, 0);
      for (std::size_t i = 0; i < strata; ++i) {
        const double x = points.point(i)[axis];
        ASSERT_TRUE(x >= 0.0 && x < 1.0);
        ++hits[static_cast<std::size_t>(x * static_cast<double>(strata))];
      }
      EXPECT_EQ(*std::min_element(hits.begin(), hits.end()), 1) << "axis " << axis;
      EXPECT_EQ(*std::max_element(hits.begin(), hits.end()), 1) << "axis " << axis;
    }
  }
}

// Enough points for the threaded loop (core/parallel.hpp) to run.
TEST(Halton, DeterministicPerSeedAndIndependentOfThreads) {
  const std::uint64_t threaded = kParallelFromCoordinates / 5 + 1;
  const PointSet big = halton_points(5, threaded, Box{0.0, 1.0}, true, 7, 1);
  ASSERT_TRUE(worth_threads(big.coordinates.size()));
  EXPECT_EQ(big.coordinates, halton_points(5, threaded, Box{0.0, 1.0}, true, 7, 2).coordinates);
  const PointSet a = halton_points(5, 1000, Box{0.0, 1.0}, true, 7, 1);
  EXPECT_EQ(a.coordinates, halton_points(5, 1000, Box{0.0, 1.0}, true, 7, 4).coordinates);
  EXPECT_NE(a.coordinates, halton_points(5, 1000, Box{0.0, 1.0}, true, 8, 1).coordinates);
  EXPECT_NE(a.coordinates, halton_points(5, 1000, Box{0.0, 1.0}, false, 7, 1).coordinates);
  EXPECT_THROW(halton_points(0, 10, Box{0.0, 1.0}, true, 7, 1), std::invalid_argument);
  EXPECT_THROW(halton_points(kHaltonMaxDimensions + 1, 10, Box{0.0, 1.0}, true, 7, 1), std::invalid_argument);
}

// Latin hypercube: on every axis each of the n strata [m/n, (m+1)/n) holds exactly one point.
TEST(LatinHypercube, OnePointPerStratumPerAxis) {
  for (int dimension = 1; dimension <= 8; ++dimension) {
    for (std::uint64_t count : {1u, 2u, 17u, 1000u}) {
      const std::uint64_t seed = 40 + static_cast<std::uint64_t>(dimension);
      SCOPED_TRACE(::testing::Message() << "dimension " << dimension << " count " << count << " seed " << seed);
      const PointSet points = latin_hypercube_points(dimension, count, Box{0.0, 2.0}, seed, 2);
      for (int axis = 0; axis < dimension; ++axis) {
        std::vector<int> hits(count, 0);
        for (std::size_t i = 0; i < count; ++i) {
          const double unit = points.point(i)[axis] / 2.0;
          ASSERT_TRUE(unit >= 0.0 && unit < 1.0);
          ++hits[static_cast<std::size_t>(unit * static_cast<double>(count))];
        }
        EXPECT_EQ(*std::max_element(hits.begin(), hits.end()), 1);
      }
    }
  }
}

TEST(LatinHypercube, DeterministicPerSeedAndIndependentOfThreads) {
  const std::uint64_t threaded = kParallelFromCoordinates / 6 + 1;
  const PointSet big = latin_hypercube_points(6, threaded, Box{0.0, 1.0}, 3, 1);
  ASSERT_TRUE(worth_threads(big.coordinates.size()));
  EXPECT_EQ(big.coordinates, latin_hypercube_points(6, threaded, Box{0.0, 1.0}, 3, 2).coordinates);
  const PointSet a = latin_hypercube_points(6, 500, Box{0.0, 1.0}, 3, 1);
  EXPECT_EQ(a.coordinates, latin_hypercube_points(6, 500, Box{0.0, 1.0}, 3, 5).coordinates);
  EXPECT_NE(a.coordinates, latin_hypercube_points(6, 500, Box{0.0, 1.0}, 4, 1).coordinates);
}

}  // namespace
}  // namespace dfvn
