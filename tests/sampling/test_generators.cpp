// Jitter, random points and curl noise jittering: bounds, determinism and thread independence.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "dfvn/core/parallel.hpp"
#include "dfvn/sampling/curl_noise_jitter.hpp"
#include "dfvn/sampling/jitter.hpp"
#include "dfvn/sampling/lattice.hpp"

namespace dfvn {
namespace {

TEST(Lattice, PaperAndUnitCoordinates) {
  const LatticeSpec paper{7, 6, Protocol::paper}, unit{7, 6, Protocol::fair};
  EXPECT_DOUBLE_EQ(paper.coordinate(0), 0.05);
  EXPECT_DOUBLE_EQ(paper.coordinate(5), 0.95);
  EXPECT_DOUBLE_EQ(paper.spacing(), 0.18);  // data/PROTOCOL.md: 0.9/5 in 7D
  EXPECT_DOUBLE_EQ(LatticeSpec({6, 7, Protocol::paper}).spacing(), 0.15);
  EXPECT_DOUBLE_EQ(unit.coordinate(0), 1.0 / 12.0);
  EXPECT_EQ(paper.point_count(), 279936u);
  EXPECT_DOUBLE_EQ(jitter_half_width(paper), 0.05);
  EXPECT_DOUBLE_EQ(jitter_half_width(unit), 1.0 / 12.0);
  EXPECT_THROW(LatticeSpec({8, 1 << 20, Protocol::fair}).point_count(), std::invalid_argument);
}

TEST(Lattice, AverageNeighbourDistance) {
  // Section 5.1's dbar: 1D: both neighbours at distance 1; 2D: (4 * 1 + 4 * sqrt 2) / 8.
  EXPECT_DOUBLE_EQ(average_neighbour_distance(1), 1.0);
  EXPECT_DOUBLE_EQ(average_neighbour_distance(2), (4.0 + 4.0 * std::sqrt(2.0)) / 8.0);
}

// 23^4 points: enough coordinates for the threaded loops (core/parallel.hpp).
TEST(Jitter, StaysInItsCellAndIgnoresThreads) {
  const LatticeSpec l{4, 23, Protocol::fair};
  const PointSet a = jittered_lattice(l, 3, 1), b = jittered_lattice(l, 3, 2);
  ASSERT_TRUE(worth_threads(a.coordinates.size()));
  EXPECT_EQ(a.coordinates, b.coordinates);
  ASSERT_EQ(a.size(), 279841u);
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
  const PointSet big = uniform_random_points(3, kParallelFromCoordinates / 3 + 1, Box{0.0, 2.0}, 4, 1);
  ASSERT_TRUE(worth_threads(big.coordinates.size()));
  EXPECT_EQ(big.coordinates, uniform_random_points(3, kParallelFromCoordinates / 3 + 1, Box{0.0, 2.0}, 4, 2).coordinates);
}

TEST(MatchedJitter, SameBytesOnOneAndTwoThreadsOnALargeLattice) {
  const LatticeSpec l{4, 23, Protocol::fair};
  const MatchedJitter a = jitter_matching_rms(l, 0.3 / 23, JitterBoundary::reflect, 5, 1);
  const MatchedJitter b = jitter_matching_rms(l, 0.3 / 23, JitterBoundary::reflect, 5, 2);
  ASSERT_TRUE(worth_threads(a.points.coordinates.size()));
  EXPECT_EQ(a.points.coordinates, b.points.coordinates);
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
  const LatticeSpec l{3, 20, Protocol::fair};
  CnjOptions o;
  const CnjResult r = curl_noise_jitter(l, o, 5, 2);
  EXPECT_GT(r.rms_displacement, 0.3 * r.trace_time);
  EXPECT_LT(r.rms_displacement, 3.0 * r.trace_time);
}

// CnjOptions's steps default to the domain's count: 1 in the bounded field, kFreeFieldSteps in the
// free one (drop mode, and the torus, the default). An explicit count is kept; a negative one is refused.
TEST(CurlNoiseJitter, StepsDefaultToTheDomainModesCount) {
  CnjOptions o;
  EXPECT_EQ(o.domain, DomainKind::torus);
  EXPECT_EQ(o.trace.steps, CnjOptions::kStepsByDomainMode);
  EXPECT_EQ(cnj_steps(o), kFreeFieldSteps);
  o.domain = DomainKind::cube;
  EXPECT_EQ(cnj_steps(o), 1);
  o.domain_mode = DomainMode::drop;
  EXPECT_EQ(cnj_steps(o), kFreeFieldSteps);
  EXPECT_EQ(cnj_trace_options(o).steps, kFreeFieldSteps);
  o.trace.steps = 3;
  EXPECT_EQ(cnj_steps(o), 3);
  o.domain_mode = DomainMode::conformant;
  EXPECT_EQ(cnj_steps(o), 3);
  o.trace.steps = -1;
  EXPECT_THROW(o.validate(), std::invalid_argument);
  o.trace.steps = CnjOptions::kMaxSteps;
  EXPECT_NO_THROW(o.validate());
  o.trace.steps = CnjOptions::kMaxSteps + 1;
  EXPECT_THROW(o.validate(), std::invalid_argument);
  o.domain_mode = DomainMode::drop;
  EXPECT_THROW(o.validate(), std::invalid_argument);
}

// The default in the bounded cube is the one-step trace, bit for bit.
TEST(CurlNoiseJitter, ConformantDefaultIsOneStep) {
  const LatticeSpec l{4, 5, Protocol::paper};
  CnjOptions bounded;
  bounded.domain = DomainKind::cube;
  CnjOptions one = bounded;
  one.trace.steps = 1;
  EXPECT_EQ(curl_noise_jitter(l, bounded, 3, 2).points.coordinates, curl_noise_jitter(l, one, 3, 2).points.coordinates);
}

// The default in drop mode is the trace with kFreeFieldSteps steps, bit for bit, and not the one-step trace.
TEST(CurlNoiseJitter, DropModeDefaultIsItsStepCount) {
  const LatticeSpec l{5, 4, Protocol::paper};
  CnjOptions automatic;
  automatic.domain = DomainKind::cube;
  automatic.domain_mode = DomainMode::drop;
  CnjOptions chosen = automatic, one = automatic;
  chosen.trace.steps = kFreeFieldSteps;
  one.trace.steps = 1;
  const CnjResult a = curl_noise_jitter(l, automatic, 3, 2);
  EXPECT_EQ(a.displacements, curl_noise_jitter(l, chosen, 3, 2).displacements);
  EXPECT_NE(a.displacements, curl_noise_jitter(l, one, 3, 2).displacements);
}

// Why the free field takes kFreeFieldSteps: in 7D, at the default frequency and trace time, one RK4 step
// lands far from the flow's end point (a trace of 16 steps); two land close to it. Measured, seed 1:
// RMS distance to the flow's end 0.25 spacings with one step, 0.065 with two.
TEST(CurlNoiseJitter, DropModeStepsFollowTheFlow) {
  const LatticeSpec l{7, 3, Protocol::paper};  // 2187 sites
  auto displacements = [&](int steps) {
    CnjOptions o;
    o.domain = DomainKind::cube;
    o.domain_mode = DomainMode::drop;
    o.trace.steps = steps;
    return curl_noise_jitter(l, o, 1, 2).displacements;
  };
  const std::vector<double> flow = displacements(16), one = displacements(1), two = displacements(kFreeFieldSteps);
  auto rms_distance = [&](const std::vector<double>& d) {
    double sum = 0.0;
    for (std::size_t i = 0; i < d.size(); ++i) sum += (d[i] - flow[i]) * (d[i] - flow[i]);
    return std::sqrt(sum / static_cast<double>(l.point_count()));
  };
  const double spacing = l.spacing();
  RecordProperty("one_step_error_spacings", std::to_string(rms_distance(one) / spacing));
  RecordProperty("two_step_error_spacings", std::to_string(rms_distance(two) / spacing));
  EXPECT_GT(rms_distance(one), 0.1 * spacing);
  EXPECT_LT(rms_distance(two), 0.5 * rms_distance(one));
}

}  // namespace
}  // namespace dfvn
