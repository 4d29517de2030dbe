// CNJ on the torus (the default domain), the bounds of the cube and the ball, and jitter-matched:
// every point kept, the wall factor measured on every point, equal movement to the last bits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dfvn/core/torus.hpp"
#include "dfvn/core/hash.hpp"
#include "dfvn/field/constraint.hpp"
#include "dfvn/integrate/trace_table.hpp"
#include "dfvn/sampling/curl_noise_jitter.hpp"
#include "dfvn/sampling/jitter.hpp"

namespace dfvn {
namespace {

int small_grid(int dimension) {
  static constexpr int kGrid[] = {0, 0, 40, 14, 7, 5, 4, 3, 3};
  return kGrid[dimension];
}

TEST(TorusJitter, KeepsEveryLatticePointInTheHalfOpenUnitCube) {
  for (int dimension = 2; dimension <= 8; ++dimension)
    for (Protocol protocol : {Protocol::paper, Protocol::fair}) {
      const LatticeSpec lattice{dimension, small_grid(dimension), protocol};
      const CnjResult r = curl_noise_jitter(lattice, CnjOptions{}, 3, 2);
      SCOPED_TRACE(::testing::Message() << dimension << "D " << to_string(protocol));
      EXPECT_EQ(r.points.size(), lattice.point_count());
      EXPECT_EQ(r.dropped, 0u);
      EXPECT_EQ(r.retraced, 0u);
      for (double x : r.points.coordinates) {
        ASSERT_GE(x, 0.0);
        ASSERT_LT(x, 1.0);
      }
      EXPECT_GT(r.rms_displacement, 0.2 * r.trace_time);  // the points did move
      // The torus starts from the cell-centred lattice whatever the protocol: its spacing is 1/K.
      EXPECT_DOUBLE_EQ(r.trace_time, 0.5 * average_neighbour_distance(dimension) / small_grid(dimension));
    }
}

TEST(TorusJitter, SameBytesOnOneAndTwoThreads) {
  const LatticeSpec l{6, 5, Protocol::fair};
  const CnjResult a = curl_noise_jitter(l, CnjOptions{}, 9, 1), b = curl_noise_jitter(l, CnjOptions{}, 9, 2);
  EXPECT_EQ(a.points.coordinates, b.points.coordinates);
  EXPECT_EQ(a.displacements, b.displacements);
  const MatchedJitter c = jitter_matching_rms(l, a.rms_displacement, JitterBoundary::wrap, 9, 1);
  const MatchedJitter d = jitter_matching_rms(l, a.rms_displacement, JitterBoundary::wrap, 9, 2);
  EXPECT_EQ(c.points.coordinates, d.points.coordinates);
}

TEST(TorusJitter, RefusesDropModeAndBasesWithoutAPeriodicForm) {
  CnjOptions o;
  o.domain_mode = DomainMode::drop;
  EXPECT_THROW(o.validate(), std::invalid_argument);
  o = CnjOptions{};
  o.noise = NoiseBasis::simplex;
  EXPECT_THROW(o.validate(), std::invalid_argument);
  EXPECT_EQ(parse_domain_kind("torus"), DomainKind::torus);
  EXPECT_THROW(parse_domain_kind("klein"), std::invalid_argument);
}

// Per coordinate, the share within [lo, hi) spacings of a face over the share within the same distance
// of an interior cell plane x = m / K (the cell-centred lattice's planes; the faces are planes too),
// each over its band's volume fraction, every point counted.
double face_over_interior(const PointSet& points, int grid, double lo, double hi) {
  std::size_t face = 0, interior = 0;
  for (double x : points.coordinates) {
    const double u = x * grid, plane = std::nearbyint(u), d = std::abs(u - plane);
    if (d < lo || d >= hi) continue;
    (plane == 0.0 || plane == grid ? face : interior) += 1;
  }
  // Two faces with one side each against K - 1 planes with two sides each.
  return (static_cast<double>(face) / 2.0) / (static_cast<double>(interior) / (2.0 * (grid - 1)));
}

// The wall factor (data/boundary_shares.md): on the torus a face is just another cell plane, and the
// face's share within a quarter spacing equals an interior plane's; in the cube bounded by Eq. 13 the
// outermost layer slides along the face half a spacing away and the band stays nearly empty (0.37 of the
// interior's in 3D at K = 30). 3D, K = 20, three seeds pooled: 24,000 coordinates per seed, of which
// about 900 in the face band, so the ratio's standard error is about 3%.
TEST(TorusJitter, FaceBandsHoldWhatInteriorPlanesHold) {
  const LatticeSpec lattice{3, 20, Protocol::fair};
  for (DomainKind domain : {DomainKind::torus, DomainKind::cube}) {
    PointSet pooled{3, {}, Box{}};
    for (std::uint64_t seed : {1, 2, 3}) {
      CnjOptions o;
      o.domain = domain;
      const CnjResult r = curl_noise_jitter(lattice, o, seed, 2);
      pooled.coordinates.insert(pooled.coordinates.end(), r.points.coordinates.begin(), r.points.coordinates.end());
    }
    const double near = face_over_interior(pooled, 20, 0.0, 0.25), far = face_over_interior(pooled, 20, 0.25, 0.5);
    std::printf("%s: face / interior share [0, h/4) %.3f, [h/4, h/2) %.3f\n", std::string(to_string(domain)).c_str(), near,
                far);
    if (domain == DomainKind::torus) {
      EXPECT_NEAR(near, 1.0, 0.12);
      EXPECT_NEAR(far, 1.0, 0.12);
    } else {  // Eq. 13: the artefact this test exists to catch
      EXPECT_LT(near, 0.6);
    }
  }
}

// Jitter-matched moves the lattice exactly as far as CNJ did: its RMS displacement equals CNJ's to
// 1e-9 relative, wrapped on the torus and reflected in the cube, and every point stays in [0,1]^N.
TEST(JitterMatched, EqualsTheRmsDisplacementItIsGiven) {
  for (int dimension = 2; dimension <= 8; ++dimension)
    for (DomainKind domain : {DomainKind::torus, DomainKind::cube}) {
      const LatticeSpec lattice{dimension, small_grid(dimension), Protocol::fair};
      CnjOptions o;
      o.domain = domain;
      const CnjResult cnj = curl_noise_jitter(lattice, o, 4, 2);
      const JitterBoundary boundary = domain == DomainKind::torus ? JitterBoundary::wrap : JitterBoundary::reflect;
      const MatchedJitter j = jitter_matching_rms(lattice, cnj.rms_displacement, boundary, 4, 2);
      double sum = 0.0;
      for (double u : j.displacements) sum += u * u;
      const double rms = std::sqrt(sum / static_cast<double>(lattice.point_count()));
      SCOPED_TRACE(::testing::Message() << dimension << "D " << to_string(domain));
      EXPECT_NEAR(rms / cnj.rms_displacement, 1.0, 1e-9);
      ASSERT_EQ(j.points.size(), lattice.point_count());
      for (double x : j.points.coordinates) {
        ASSERT_GE(x, 0.0);
        ASSERT_LE(x, 1.0);
        if (boundary == JitterBoundary::wrap) ASSERT_LT(x, 1.0);
      }
      // The same draws as plain jitter: at the protocol's half-width a matched jitter is that jitter.
      if (domain == DomainKind::torus) {
        const PointSet plain = jittered_lattice(lattice, j.half_width, 4, 2);
        PointSet wrapped = plain;
        wrap_to_unit_torus(wrapped.coordinates.data(), wrapped.coordinates.size());
        EXPECT_EQ(wrapped.coordinates, j.points.coordinates);
      }
    }
}

TEST(JitterMatched, RefusesWhatItCannotMatch) {
  const LatticeSpec lattice{2, 10, Protocol::fair};
  for (double bad : {0.0, -1.0, std::nan(""), HUGE_VAL})
    EXPECT_THROW(jitter_matching_rms(lattice, bad, JitterBoundary::wrap, 1, 1), std::invalid_argument) << bad;
  // Reflected into the unit square, no point can move an RMS of 5.
  EXPECT_THROW(jitter_matching_rms(lattice, 5.0, JitterBoundary::reflect, 1, 1), std::invalid_argument);
}

// No trace leaves its domain: 10^5 starts uniform in the cube and the ball, every bound, 2D-8D, traced as
// conformant CNJ traces (RK4 + Gauss-Newton, a retrace with more steps where a step jumped out). Every
// end lies in the domain, and a start kept where no retrace stays inside is rare.
TEST(Bounds, NoTraceLeavesTheDomain) {
  constexpr int kStarts = 100000;
  for (Bound bound : kAllBounds) {
    std::uint64_t kept = 0, retraced = 0, traced = 0;
    for (int dimension = 2; dimension <= 8; ++dimension)
      for (FieldConstraint constraint : {FieldConstraint::inside_cube, FieldConstraint::inside_ball})
        dispatch_dimension(dimension, [&]<int N>() {
          const std::size_t rows = kStarts / 14;
          FieldOptions field_options{kDefaultNoiseBasis, 2.0, constraint, 0.05, bound};
          const DfvnField<N> field(7, field_options);
          std::vector<double> starts;
          for (std::size_t i = 0; starts.size() < rows * N; ++i) {
            Vec<N> x;
            for (int j = 0; j < N; ++j) x[j] = random_unit(7, Stream::test, i, static_cast<std::uint64_t>(j));
            if (satisfies_constraint<N>(constraint, x)) starts.insert(starts.end(), x.data(), x.data() + N);
          }
          std::vector<double> ends(starts.size());
          const TracedPoints t = trace_table<N>(
              field, TraceOptions{}, starts.data(), rows, ends.data(), 0.08,
              [&](const Vec<N>& x) { return satisfies_constraint<N>(constraint, x); }, OnReject::retrace, 2, {});
          for (std::size_t i = 0; i < rows; ++i)
            ASSERT_TRUE(satisfies_constraint<N>(constraint, Eigen::Map<const Vec<N>>(ends.data() + i * N)))
                << N << "D " << to_string(constraint) << " " << to_string(bound) << " trace " << i;
          kept += t.kept_at_start;
          retraced += t.retraced;
          traced += rows;
        });
    std::printf("%s: %llu traces, %llu retraced, %llu kept at their start\n", std::string(to_string(bound)).c_str(),
                static_cast<unsigned long long>(traced), static_cast<unsigned long long>(retraced),
                static_cast<unsigned long long>(kept));
    EXPECT_GE(traced, 99000u);
    EXPECT_LE(kept, traced / 1000);
  }
}

}  // namespace
}  // namespace dfvn
