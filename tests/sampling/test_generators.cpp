// Jitter, random points and curl noise jittering: bounds, determinism and thread independence.
#include <gtest/gtest.h>

#include <cmath>

#include "sampling/curl_noise_jitter.hpp"
#include "sampling/jitter.hpp"
#include "sampling/lattice.hpp"

namespace dfvn {
namespace {

TEST(Lattice, PaperAndUnitCoordinates) {
  const LatticeSpec paper{7, 6, Protocol::paper}, unit{7, 6, Protocol::unit};
  EXPECT_DOUBLE_EQ(paper.coordinate(0), 0.05);
  EXPECT_DOUBLE_EQ(paper.coordinate(5), 0.95);
  EXPECT_DOUBLE_EQ(paper.spacing(), 0.18);  // data/PROTOCOL.md: 0.9/5 in 7D
  EXPECT_DOUBLE_EQ(LatticeSpec({6, 7, Protocol::paper}).spacing(), 0.15);
  EXPECT_DOUBLE_EQ(unit.coordinate(0), 1.0 / 12.0);
  EXPECT_EQ(paper.point_count(), 279936u);
  EXPECT_DOUBLE_EQ(jitter_half_width(paper), 0.05);
  EXPECT_DOUBLE_EQ(jitter_half_width(unit), 1.0 / 12.0);
  EXPECT_THROW(LatticeSpec({8, 1 << 20, Protocol::unit}).point_count(), std::invalid_argument);
}

TEST(Lattice, AverageNeighbourDistance) {
  // Section 5.1's dbar: 1D: both neighbours at distance 1; 2D: (4 * 1 + 4 * sqrt 2) / 8.
  EXPECT_DOUBLE_EQ(average_neighbour_distance(1), 1.0);
  EXPECT_DOUBLE_EQ(average_neighbour_distance(2), (4.0 + 4.0 * std::sqrt(2.0)) / 8.0);
}

TEST(Jitter, StaysInItsCellAndIgnoresThreads) {
  const LatticeSpec l{4, 5, Protocol::unit};
  const PointSet a = jittered_lattice(l, 3, 1), b = jittered_lattice(l, 3, 2);
  EXPECT_EQ(a.coordinates, b.coordinates);
  ASSERT_EQ(a.size(), 625u);
  double lattice[4];
  for (std::size_t i = 0; i < a.size(); ++i) {
    l.point(i, lattice);
    for (int j = 0; j < 4; ++j) EXPECT_LE(std::abs(a.point(i)[j] - lattice[j]), 0.1);
  }
}

TEST(RandomPoints, UniformInTheDomain) {
  const PointSet p = uniform_random_points(3, 30000, Box{0.0, 2.0}, 4, 2);
  double mean = 0.0;
  for (double x : p.coordinates) {
    EXPECT_GE(x, 0.0);
    EXPECT_LT(x, 2.0);
    mean += x / static_cast<double>(p.coordinates.size());
  }
  EXPECT_NEAR(mean, 1.0, 0.02);  // standard error 2/sqrt(12 * 90000) = 0.002
}

TEST(CurlNoiseJitter, SameBytesOnOneAndTwoThreads) {
  for (int dimension : {3, 5, 7}) {
    const LatticeSpec l{dimension, dimension == 7 ? 4 : 8, Protocol::paper};
    const CnjResult a = curl_noise_jitter(l, CnjOptions{}, 17, 1);
    const CnjResult b = curl_noise_jitter(l, CnjOptions{}, 17, 2);
    EXPECT_EQ(a.points.coordinates, b.points.coordinates) << dimension << "D";
    EXPECT_EQ(a.dropped, b.dropped);
    EXPECT_EQ(a.rms_displacement, b.rms_displacement);
    EXPECT_EQ(a.points.size() + a.dropped, l.point_count());
    for (std::size_t i = 0; i < a.points.size(); ++i) EXPECT_TRUE(Box{}.contains(a.points.point(i), dimension));
  }
}

TEST(CurlNoiseJitter, MovesPointsByAboutTheTraceTime) {
  // RMS |c| = 1, so a single RK4 step of time t moves points by about t in the RMS sense.
  const LatticeSpec l{3, 20, Protocol::unit};
  CnjOptions o;
  const CnjResult r = curl_noise_jitter(l, o, 5, 2);
  EXPECT_GT(r.rms_displacement, 0.3 * r.trace_time);
  EXPECT_LT(r.rms_displacement, 3.0 * r.trace_time);
}

}  // namespace
}  // namespace dfvn
