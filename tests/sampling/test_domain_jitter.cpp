// Curl noise jittering that stays in its domain (Eq. 13) and on the sphere (Section 4).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dfvn/field/constraint.hpp"
#include "dfvn/sampling/curl_noise_jitter.hpp"
#include "dfvn/sampling/sphere_jitter.hpp"
#include "dfvn/stats/geodesic.hpp"

namespace dfvn {
namespace {

// K per dimension so that K^N stays small (the 8D lattice of K = 3 still has 6561 points).
int small_grid(int dimension) {
  static constexpr int kGrid[] = {0, 0, 40, 14, 7, 5, 4, 3, 3};
  return kGrid[dimension];
}

TEST(ConformantJitter, KeepsEveryPointInsideTheCubeAndTheBall) {
  for (int dimension = 2; dimension <= 8; ++dimension)
    for (DomainKind domain : {DomainKind::cube, DomainKind::ball})
      for (Bound bound : kAllBounds)
      for (Protocol protocol : {Protocol::paper, Protocol::fair})
        for (std::uint64_t seed : {1, 2}) {
          const LatticeSpec lattice{dimension, small_grid(dimension) + (domain == DomainKind::ball ? 2 : 0), protocol};
          CnjOptions options;
          options.domain = domain;
          options.bound = bound;
          const CnjResult r = curl_noise_jitter(lattice, options, seed, 2);
          SCOPED_TRACE(::testing::Message() << dimension << "D " << to_string(domain) << " " << to_string(bound) << " "
                                            << to_string(protocol) << " seed " << seed);
          EXPECT_EQ(r.dropped, 0u);
          EXPECT_EQ(r.points.size(), r.started);
          EXPECT_EQ(r.started, cnj_start_count(lattice, domain));
          EXPECT_GT(r.started, 0u);
          for (std::size_t i = 0; i < r.points.size(); ++i)
            ASSERT_TRUE(r.points.domain.contains(r.points.point(i), dimension)) << "point " << i;
          // The fallback is rare: nearly every point is moved by its first trace.
          EXPECT_LE(r.kept_at_site, r.started / 100 + 1);
          if (r.retraced > 0)
            std::printf("%dD %s %s seed %d: %llu of %llu retraced, %llu kept at their site\n", dimension,
                        std::string(to_string(domain)).c_str(), std::string(to_string(protocol)).c_str(),
                        static_cast<int>(seed), static_cast<unsigned long long>(r.retraced),
                        static_cast<unsigned long long>(r.started), static_cast<unsigned long long>(r.kept_at_site));
        }
}

TEST(ConformantJitter, BallLatticeIsTheLatticeClippedToTheInscribedBall) {
  const LatticeSpec lattice{2, 10, Protocol::fair};
  // Cell centres (i + 1/2)/10 strictly inside the circle of radius 1/2 about (1/2, 1/2), in cell units:
  std::uint64_t expected = 0;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) expected += (i - 4.5) * (i - 4.5) + (j - 4.5) * (j - 4.5) < 25.0;
  EXPECT_EQ(cnj_start_count(lattice, DomainKind::ball), expected);
  EXPECT_EQ(expected, 80u);  // 100 minus the 5 cells in each corner whose centres lie outside
  EXPECT_EQ(cnj_start_sites(lattice, DomainKind::ball).size(), 2 * expected);
}

// A step much longer than the boundary layer jumps across it; conformant CNJ then traces again with
// more steps (or keeps the point at its site) and still returns every point inside.
TEST(ConformantJitter, RetracesStepsThatJumpOutOfTheDomain) {
  const LatticeSpec lattice{3, 10, Protocol::paper};
  CnjOptions options;
  options.domain = DomainKind::cube;
  options.step_scale = 8.0;
  const CnjResult r = curl_noise_jitter(lattice, options, 5, 2);
  std::printf("step scale 8: %llu retraced, %llu kept at site\n", static_cast<unsigned long long>(r.retraced),
              static_cast<unsigned long long>(r.kept_at_site));
  EXPECT_GT(r.retraced, 0u);
  EXPECT_EQ(r.dropped, 0u);
  EXPECT_EQ(r.points.size(), lattice.point_count());
  for (std::size_t i = 0; i < r.points.size(); ++i) ASSERT_TRUE(Box{}.contains(r.points.point(i), 3));
  options.domain_mode = DomainMode::drop;
  EXPECT_GT(curl_noise_jitter(lattice, options, 5, 2).dropped, 0u);  // the free field loses them
}

TEST(ConformantJitter, SameBytesOnOneAndTwoThreads) {
  for (DomainKind domain : {DomainKind::cube, DomainKind::ball}) {
    const LatticeSpec l{5, 6, Protocol::paper};
    CnjOptions options;
    options.domain = domain;
    const CnjResult a = curl_noise_jitter(l, options, 17, 1);
    const CnjResult b = curl_noise_jitter(l, options, 17, 2);
    EXPECT_EQ(a.points.coordinates, b.points.coordinates);
    EXPECT_EQ(a.retraced, b.retraced);
  }
}

// The bounded field is volume-preserving and maps the cube onto itself, so a start set that is
// uniform (the cell-centred lattice of the unit protocol) stays uniform: the fraction of points in the
// boundary layer of width one spacing must equal the layer's volume fraction 1 - (1 - 2/K)^N. The
// tolerance is 3 binomial standard errors sqrt(p (1 - p) / n), what independent uniform points would
// scatter by. Dropping CNJ loses the points that cross the faces and gains none: its layer is thinner.
// (With a transition of one spacing instead of the default half, the conformant layer held 3-10
// standard errors too many points: data/boundary_width.md.)
struct LayerFraction {
  double conformant, dropped, expected, standard_error;
};

LayerFraction boundary_layer_fraction(int dimension, int grid, std::uint64_t seed) {
  const LatticeSpec lattice{dimension, grid, Protocol::fair};
  const double w = 1.0 / grid;
  auto fraction_in_layer = [&](const PointSet& points) {
    std::size_t in_layer = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      bool near = false;
      for (int j = 0; j < dimension; ++j) near = near || points.point(i)[j] < w || points.point(i)[j] > 1.0 - w;
      in_layer += near;
    }
    return static_cast<double>(in_layer) / static_cast<double>(points.size());
  };
  CnjOptions options;
  options.domain = DomainKind::cube;
  const CnjResult conformant = curl_noise_jitter(lattice, options, seed, 2);
  options.domain_mode = DomainMode::drop;
  const CnjResult dropped = curl_noise_jitter(lattice, options, seed, 2);
  const double p = 1.0 - std::pow(1.0 - 2.0 * w, dimension);
  return {fraction_in_layer(conformant.points), fraction_in_layer(dropped.points), p,
          std::sqrt(p * (1.0 - p) / static_cast<double>(conformant.points.size()))};
}

TEST(ConformantJitter, BoundaryLayerHoldsItsVolumeFraction) {
  for (auto [dimension, grid] : {std::pair{3, 40}, std::pair{6, 7}})
    for (std::uint64_t seed : {1, 2, 3}) {
      const LayerFraction f = boundary_layer_fraction(dimension, grid, seed);
      std::printf("%dD K=%d seed %d: layer fraction conformant %.5f, dropped %.5f, volume %.5f, SE %.5f\n", dimension,
                  grid, static_cast<int>(seed), f.conformant, f.dropped, f.expected, f.standard_error);
      EXPECT_LE(std::abs(f.conformant - f.expected), 3.0 * f.standard_error) << dimension << "D seed " << seed;
      EXPECT_LT(f.dropped, f.expected - 3.0 * f.standard_error) << dimension << "D seed " << seed;
    }
}

TEST(SphereJitter, EveryPointStaysOnTheSphere) {
  for (int dimension = 3; dimension <= 8; ++dimension)
    for (std::uint64_t seed : {1, 2}) {
      const int grid = dimension <= 4 ? 12 : (dimension <= 6 ? 6 : 4);
      const SphereCnjResult r = sphere_curl_noise_jitter(dimension, grid, CnjOptions{}, seed, 2);
      const PointSet start = sphere_start_set(dimension, grid);
      ASSERT_EQ(r.points.size(), start.size());
      ASSERT_GT(r.points.size(), 10u);
      double worst = 0.0;
      for (std::size_t i = 0; i < r.points.size(); ++i) {
        double r2 = 0.0;
        for (int j = 0; j < dimension; ++j) r2 += r.points.point(i)[j] * r.points.point(i)[j];
        worst = std::max(worst, std::abs(std::sqrt(r2) - 1.0));
      }
      std::printf("%dD sphere, %zu points: max ||x| - 1| = %.3g, rms move %.4g, %llu retraced, %llu kept\n", dimension,
                  r.points.size(), worst, r.rms_displacement, static_cast<unsigned long long>(r.retraced),
                  static_cast<unsigned long long>(r.kept_at_site));
      EXPECT_LE(worst, 1e-12);
      EXPECT_GT(r.rms_displacement, 0.2 * r.trace_time);  // the points did move
      EXPECT_LE(r.kept_at_site, r.points.size() / 100 + 1);
    }
}

// The sphere traces as a conformant domain whatever the domain mode says: the same points, one step.
TEST(SphereJitter, TracesAsConformantInEveryDomainMode) {
  CnjOptions drop;
  drop.domain_mode = DomainMode::drop;
  EXPECT_EQ(sphere_cnj_options(drop).domain_mode, DomainMode::conformant);
  EXPECT_EQ(cnj_steps(sphere_cnj_options(drop)), 1);
  const SphereCnjResult a = sphere_curl_noise_jitter(4, 6, drop, 2, 2);
  const SphereCnjResult b = sphere_curl_noise_jitter(4, 6, CnjOptions{}, 2, 2);
  EXPECT_EQ(a.points.coordinates, b.points.coordinates);
  // A step count the domain mode does not bound is still bounded on the sphere, which refines it.
  drop.trace.steps = CnjOptions::kMaxSteps + 1;
  EXPECT_THROW(sphere_curl_noise_jitter(4, 6, drop, 2, 2), std::invalid_argument);
}

TEST(SphereJitter, GeodesicNearestNeighboursEqualBruteForce) {
  for (int dimension = 3; dimension <= 8; ++dimension) {
    const SphereCnjResult r = sphere_curl_noise_jitter(dimension, dimension <= 5 ? 8 : 4, CnjOptions{}, 3, 2);
    for (const PointSet& points : {r.points, uniform_points_on_sphere(dimension, 1500, 3, 2)}) {
      const std::vector<double> tree = geodesic_nearest_neighbour_distances(points, KnnBackend::nanoflann, 2);
      const std::vector<double> brute = geodesic_nearest_neighbour_distances_brute_force(points);
      ASSERT_EQ(tree.size(), brute.size());
      for (std::size_t i = 0; i < tree.size(); ++i) ASSERT_NEAR(tree[i], brute[i], 1e-9 * (1.0 + brute[i])) << i;
    }
  }
}

TEST(SphereJitter, RandomPointsAreUniformOnTheSphere) {
  const PointSet p = uniform_points_on_sphere(5, 20000, 9, 2);
  std::vector<double> mean(5, 0.0), second(5, 0.0);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int j = 0; j < 5; ++j) {
      mean[j] += p.point(i)[j] / 20000.0;
      second[j] += p.point(i)[j] * p.point(i)[j] / 20000.0;
    }
  for (int j = 0; j < 5; ++j) {
    EXPECT_NEAR(mean[j], 0.0, 4.0 * std::sqrt(0.2 / 20000.0));  // E x_j = 0, Var x_j = 1/N
    EXPECT_NEAR(second[j], 0.2, 0.01);
  }
}

TEST(SphereJitter, SpreadsBetterThanRandomPoints) {
  for (int dimension = 3; dimension <= 8; ++dimension) {
    const int grid = dimension <= 4 ? 12 : (dimension <= 6 ? 6 : 4);
    const SphereCnjResult r = sphere_curl_noise_jitter(dimension, grid, CnjOptions{}, 1, 2);
    const PointSet random = uniform_points_on_sphere(dimension, r.points.size(), 1, 2);
    const NearestNeighbourSummary cnj = summarize_geodesic_nearest_neighbours(
        geodesic_nearest_neighbour_distances(r.points, KnnBackend::nanoflann, 2), dimension);
    const NearestNeighbourSummary uniform = summarize_geodesic_nearest_neighbours(
        geodesic_nearest_neighbour_distances(random, KnnBackend::nanoflann, 2), dimension);
    std::printf("%dD sphere, %zu points: cnj min %.4f q01 %.4f median %.4f | random min %.4f q01 %.4f median %.4f\n",
                dimension, r.points.size(), cnj.min, cnj.q01, cnj.median, uniform.min, uniform.q01, uniform.median);
    EXPECT_GT(cnj.q01, uniform.q01);
    EXPECT_GT(cnj.median, uniform.median);
  }
}

}  // namespace
}  // namespace dfvn
