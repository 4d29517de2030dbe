// Issue 23: statistics at any scale. A set scaled by 10^k (with its domain) has the statistics of the
// unscaled set times 10^k, or the scale is refused with one line naming the bound; extreme domains
// crashed the KD-tree (squared distances Inf) and wrote Inf and NaN.
#include "dfvn/stats/distance_scale.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "dfvn/sampling/jitter.hpp"
#include "dfvn/stats/point_set_statistics.hpp"
#include "dfvn/stats/radial_distribution.hpp"

namespace dfvn {
namespace {

// 200 uniform random points in [0.05, 0.95]^N scaled to [0, side]^N, and the domain with them.
PointSet test_set(int dimension, double side) {
  PointSet p = uniform_random_points(dimension, 200, Box{0.05, 0.9}, 23 + dimension, 1);
  for (double& x : p.coordinates) x *= side;
  p.domain = Box{0.0, side};
  return p;
}

// 10^k for k = -330..330 (each k from 298 to 302 on both sides, where the bounds 2^-1000 = 9.3e-302
// and 2^1000 = 1.1e301 lie): inside [2^-1000, 2^1000] every statistic is the
// unit set's times 10^k (the scaled median the same), to the rounding of x * 10^k; outside, the side
// is refused naming the bound.
TEST(DistanceScale, NearestNeighbourStatisticsScaleWithTheSetOrTheScaleIsRefused) {
  for (int dimension : {1, 2, 3, 5, 8}) {
    PointSetStatisticsOptions options;
    options.threads = 2;
    const NearestNeighbourSummary unit = measure_point_set(test_set(dimension, 1.0), options).nearest;
    for (int k = -330; k <= 330; k += (std::abs(k) >= 298 && std::abs(k) <= 302) ? 1 : 10) {
      const double side = std::strtod(("1e" + std::to_string(k)).c_str(), nullptr);  // 0 or Inf beyond the doubles
      const PointSet scaled = test_set(dimension, side);
      const bool supported = side >= kMinDomainSide && side <= kMaxDomainSide;
      SCOPED_TRACE(std::to_string(dimension) + "D, side 1e" + std::to_string(k));
      for (KnnBackend knn : {KnnBackend::nanoflann, KnnBackend::flann}) {
        options.knn = knn;
        if (!supported) {
          try {
            measure_point_set(scaled, options);
            ADD_FAILURE() << "side accepted";
          } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("outside [2^-1000, 2^1000]"), std::string::npos) << e.what();
          }
          continue;
        }
        const NearestNeighbourSummary s = measure_point_set(scaled, options).nearest;
        EXPECT_EQ(s.points, unit.points);
        // x * 10^k rounds each coordinate by half an ulp (1.1e-16 of the side): distances, differences
        // of coordinates, move by a few of those in units of the side.
        EXPECT_NEAR(s.min / side, unit.min, 1e-14);
        EXPECT_NEAR(s.q01 / side, unit.q01, 1e-14);
        EXPECT_NEAR(s.median / side, unit.median, 1e-14);
        EXPECT_NEAR(s.mean / side, unit.mean, 1e-14);
        EXPECT_NEAR(s.median_scaled, unit.median_scaled, 1e-12 * unit.median_scaled);
      }
    }
  }
}

// Powers of two scale exactly: the same bits at every supported scale, through whichever path.
TEST(DistanceScale, PowersOfTwoGiveTheSameBits) {
  for (int dimension : {2, 4, 8}) {
    const PointSet unit = test_set(dimension, 1.0);
    const auto unit_distances = nearest_neighbour_distances(unit, KnnBackend::nanoflann, 1);
    const NearestNeighbourSummary unit_summary = summarize_nearest_neighbours(unit_distances, unit);
    RdfOptions rdf;
    rdf.bins = 20;
    const RdfCurve unit_rdf = radial_distribution(unit, rdf, 1, 2);
    for (int e = -1000; e <= 1000; e += 50) {
      SCOPED_TRACE(std::to_string(dimension) + "D, side 2^" + std::to_string(e));
      const double side = std::ldexp(1.0, e);
      const PointSet scaled = test_set(dimension, side);
      const auto distances = nearest_neighbour_distances(scaled, KnnBackend::flann, 2);
      for (std::size_t i = 0; i < distances.size(); ++i) ASSERT_EQ(distances[i], std::ldexp(unit_distances[i], e));
      const NearestNeighbourSummary s = summarize_nearest_neighbours(distances, scaled);
      EXPECT_EQ(s.median, std::ldexp(unit_summary.median, e));
      EXPECT_EQ(s.median_scaled, unit_summary.median_scaled);
      const RdfCurve curve = radial_distribution(scaled, rdf, 1, 2);
      ASSERT_EQ(curve.g.size(), unit_rdf.g.size());
      EXPECT_EQ(curve.r_max, std::ldexp(unit_rdf.r_max, e));
      for (std::size_t b = 0; b < curve.g.size(); ++b) {
        EXPECT_EQ(curve.r[b], std::ldexp(unit_rdf.r[b], e));
        EXPECT_EQ(curve.g[b], unit_rdf.g[b]) << "bin " << b;
      }
    }
  }
}

// Points of a unit domain closer than 2^-510 (their squared distance underflows) are refused unless
// they are equal; duplicates keep their distance 0.
TEST(DistanceScale, UnresolvableNeighboursAreRefusedDuplicatesAreNot) {
  PointSetStatisticsOptions options;
  const PointSet duplicates{2, {0.5, 0.5, 0.5, 0.5, 0.25, 0.75}, Box{0.0, 1.0}};
  EXPECT_EQ(measure_point_set(duplicates, options).nearest.min, 0.0);
  for (double gap : {1e-200, 1e-160, 2e-154}) {
    const PointSet close{2, {0.5, 0.5, 0.5, 0.5 + gap * 0.5, 0.1, 0.9, 0.0, 0.0, gap, 0.0}, Box{0.0, 1.0}};
    try {
      measure_point_set(close, options);
      ADD_FAILURE() << gap << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("closer than 2^-510"), std::string::npos) << e.what();
    }
  }
  // 1D needs no squares: any gap is exact.
  const PointSet line{1, {0.5, 0.5 + 1e-300, 0.25}, Box{0.0, 1.0}};
  EXPECT_EQ(measure_point_set(line, options).nearest.min, (0.5 + 1e-300) - 0.5);
  // Just above the bound, distances are found exactly.
  const PointSet resolved{2, {0.0, 0.0, 1e-150, 0.0, 0.5, 0.5}, Box{0.0, 1.0}};
  EXPECT_EQ(measure_point_set(resolved, options).nearest.min, 1e-150);
}

TEST(DistanceScale, NonFiniteCoordinatesAreNamed) {
  const PointSet bad{2, {0.5, 0.5, 0.25, std::nan("")}, Box{0.0, 1.0}};
  try {
    nearest_neighbour_distances(bad, KnnBackend::nanoflann, 1);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "point 1 (0-based) has x1 = nan; coordinates must be finite");
  }
}

}  // namespace
}  // namespace dfvn
