// Minimum-image statistics on the torus (stats/periodic_neighbours.hpp, RdfOptions::periodic).
#include "dfvn/stats/periodic_neighbours.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dfvn/core/dimension.hpp"
#include "dfvn/core/simd.hpp"
#include "dfvn/sampling/jitter.hpp"
#include "dfvn/sampling/lattice.hpp"
#include "dfvn/stats/nearest_neighbour.hpp"
#include "dfvn/stats/nearest_other.hpp"
#include "dfvn/stats/radial_distribution.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

// The KD-tree with its images equals the brute force to the last bit, 1D-8D, in boxes that do not start
// at 0, with duplicates and with points on both faces of an axis (the same point of the torus).
TEST(PeriodicNeighbours, KdTreeEqualsBruteForce) {
  for (int dimension = 1; dimension <= 8; ++dimension) {
    const Box box{-2.0, 3.0};
    PointSet p = uniform_random_points(dimension, dimension == 1 ? 300 : 2500, box, 40 + dimension, 2);
    for (int k = 0; k < 3; ++k) p.coordinates.insert(p.coordinates.end(), p.point(k * 5), p.point(k * 5) + dimension);
    std::vector<double> on_face(dimension, 0.5), opposite(dimension, 0.5);
    on_face[0] = box.lo;
    opposite[0] = box.lo + box.side;
    p.coordinates.insert(p.coordinates.end(), on_face.begin(), on_face.end());
    p.coordinates.insert(p.coordinates.end(), opposite.begin(), opposite.end());
    const auto brute = periodic_nearest_neighbour_distances_brute_force(p);
    const auto tree = periodic_nearest_neighbour_distances(p, 2);
    ASSERT_EQ(tree.size(), brute.size());
    for (std::size_t i = 0; i < brute.size(); ++i) EXPECT_EQ(tree[i], brute[i]) << dimension << "D point " << i;
    EXPECT_EQ(tree[0], 0.0);             // a duplicate
    EXPECT_EQ(tree[p.size() - 1], 0.0);  // the two faces meet
  }
}

// Every build of the periodic search this CPU runs (baseline, AVX2, AVX-512: stats/nearest_other.hpp), over
// trees with leaves of up to 10 and 64 points, finds for every point a row at brute force's minimum-image
// distance, to the bit: 2D-8D random points with duplicates, a point on each face of an axis and points a
// hair inside both faces, and a lattice with exact ties across the faces; in a box that does not start at 0
// and in one far from the origin (where the ways round through a face are computed from large numbers).
template <int N, int Lanes>
std::vector<double> periodic_search(const PointSet& p, nearest_other::NearestRows<N, Lanes> rows, int leaf) {
  const std::vector<std::uint32_t> nearest =
      nearest_other::nearest_of_every_point<N, Lanes>(p, rows, leaf, nearest_other::periodic_torus(p.domain.lo, p.domain.side));
  std::vector<double> distances(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_NE(nearest[i], i);
    distances[i] = periodic_distance_between(p, i, nearest[i]);
  }
  return distances;
}

TEST(PeriodicNeighbours, EveryBuildEqualsBruteForce) {
  for (const Box box : {Box{-2.0, 3.0}, Box{1000.25, 0.75}})
    for (int dimension = 2; dimension <= 8; ++dimension) {
      PointSet random = uniform_random_points(dimension, 2000, box, 90 + dimension, 1);
      for (int k = 0; k < 3; ++k) random.coordinates.insert(random.coordinates.end(), random.point(k * 5), random.point(k * 5) + dimension);
      for (const double x0 : {box.lo, box.lo + box.side, std::nextafter(box.lo, 1e9), std::nextafter(box.lo + box.side, -1e9)}) {
        std::vector<double> x(dimension, box.lo + 0.5 * box.side);
        x[0] = x0;
        random.coordinates.insert(random.coordinates.end(), x.begin(), x.end());
      }
      const int side = dimension >= 7 ? 3 : dimension == 6 ? 4 : dimension == 5 ? 5 : dimension == 4 ? 7 : dimension == 3 ? 12 : 40;
      PointSet lattice = testing::fair_lattice_in(dimension, side, box);
      dispatch_dimension(dimension, [&]<int N>() {
        for (const PointSet* p : {&random, &lattice}) {
          const std::vector<double> brute = periodic_nearest_neighbour_distances_brute_force(*p);
          const std::string what = std::to_string(N) + "D " + (p == &random ? "random" : "lattice") + " in [" + std::to_string(box.lo) + ", +" + std::to_string(box.side) + "]";
          for (const int leaf : {10, nearest_other::kLeafSize}) {
            EXPECT_EQ((periodic_search<N, 4>(*p, &nearest_other::baseline::nearest_rows<N, true>, leaf)), brute) << what << " baseline, leaf " << leaf;
#if defined(__x86_64__)
            if (cpu_has_avx2()) {
              EXPECT_EQ((periodic_search<N, 4>(*p, &nearest_other::avx2::nearest_rows<N, true>, leaf)), brute) << what << " AVX2, leaf " << leaf;
            }
            if (cpu_has_avx512()) {
              EXPECT_EQ((periodic_search<N, 8>(*p, &nearest_other::avx512::nearest_rows<N, true>, leaf)), brute) << what << " AVX-512, leaf " << leaf;
            }
#endif
          }
        }
      });
    }
}

// Two points near opposite faces are neighbours across them; the Euclidean distance does not see it.
TEST(PeriodicNeighbours, NeighboursAcrossTheFaces) {
  PointSet p{2, {0.01, 0.5, 0.98, 0.5, 0.5, 0.1}, Box{0.0, 1.0}};
  const auto d = periodic_nearest_neighbour_distances(p, 1);
  EXPECT_NEAR(d[0], 0.03, 1e-12);
  EXPECT_NEAR(d[1], 0.03, 1e-12);
  EXPECT_NEAR(nearest_neighbour_distances(p, KnnBackend::nanoflann, 1)[0], std::hypot(0.49, 0.4), 1e-12);
}

// A cell-centred lattice is perfectly periodic: every minimum-image distance is the spacing.
TEST(PeriodicNeighbours, LatticeOnTheTorus) {
  const LatticeSpec l{4, 5, Protocol::fair};
  PointSet p{4, Coordinates(4 * 625, 0.0), Box{0.0, 1.0}};
  for (std::uint64_t i = 0; i < 625; ++i) l.point(i, p.coordinates.data() + 4 * i);
  for (double d : periodic_nearest_neighbour_distances(p, 2)) EXPECT_NEAR(d, 0.2, 1e-12);
}

TEST(PeriodicNeighbours, IndependentOfThreadsAndRefusesPointsOutsideTheBox) {
  const PointSet p = uniform_random_points(6, 20000, Box{0.0, 1.0}, 8, 2);
  EXPECT_EQ(periodic_nearest_neighbour_distances(p, 1), periodic_nearest_neighbour_distances(p, 2));
  PointSet outside{2, {0.5, 0.5, 1.5, 0.2}, Box{0.0, 1.0}};
  EXPECT_THROW(periodic_nearest_neighbour_distances(outside, 1), std::invalid_argument);
  PointSet one{2, {0.5, 0.5}, Box{0.0, 1.0}};
  EXPECT_THROW(periodic_nearest_neighbour_distances(one, 1), std::invalid_argument);
}

// periodic_nearest_neighbour_distances_of_first(points, q): the first q values of the full function and of
// brute force, to the bit, for q = 0, 1, a middle count and n, on 1 and 2 threads, 1D-8D, random sets and
// lattices (exact ties, across the faces too) with duplicates, shuffled, in a box that does not start at 0.
TEST(PeriodicNeighbours, OfFirstEqualsTheFullFunctionAndBruteForce) {
  for (int dimension = 1; dimension <= 8; ++dimension)
    for (bool lattice : {false, true}) {
      const Box box{-2.0, 3.0};
      PointSet p{dimension, {}, box};
      if (lattice) {
        const int side = dimension >= 7 ? 3 : dimension == 6 ? 4 : dimension == 5 ? 5 : dimension == 4 ? 7 : dimension == 3 ? 12 : dimension == 2 ? 40 : 300;
        const LatticeSpec l{dimension, side, Protocol::fair};
        p.coordinates.resize(l.point_count() * static_cast<std::size_t>(dimension));
        for (std::uint64_t i = 0; i < l.point_count(); ++i) l.point(i, p.coordinates.data() + static_cast<std::size_t>(dimension) * i);
        for (double& x : p.coordinates) x = box.lo + box.side * x;  // 3 * (k + 0.5) / side: exact ties on most axes
      } else {
        p = uniform_random_points(dimension, dimension == 1 ? 300 : 1500, box, 70 + static_cast<std::uint64_t>(dimension), 1);
      }
      for (int k = 0; k < 3; ++k) p.coordinates.insert(p.coordinates.end(), p.point(k * 7), p.point(k * 7) + dimension);
      const std::size_t n = p.size();
      for (std::size_t i = n - 1; i > 0; --i) {
        const std::size_t j = (i * 2654435761u + static_cast<std::size_t>(dimension) * 40503u) % (i + 1);
        std::swap_ranges(p.coordinates.data() + i * static_cast<std::size_t>(dimension), p.coordinates.data() + (i + 1) * static_cast<std::size_t>(dimension),
                     p.coordinates.data() + j * static_cast<std::size_t>(dimension));
      }
      const auto brute = periodic_nearest_neighbour_distances_brute_force(p);
      const auto full = periodic_nearest_neighbour_distances(p, 2);
      ASSERT_EQ(full, brute) << dimension << "D";
      for (std::size_t q : {std::size_t{0}, std::size_t{1}, n / 3, n - 1, n})
        for (int threads : {1, 2}) {
          if (threads == 1 && q != n / 3) continue;  // one thread once: the answer is the same
          const auto first = periodic_nearest_neighbour_distances_of_first(p, q, threads);
          ASSERT_EQ(first.size(), q);
          for (std::size_t i = 0; i < q; ++i)
            ASSERT_EQ(first[i], full[i]) << dimension << "D " << (lattice ? "lattice" : "random") << " q = " << q << " point " << i;
        }
    }
}

// The unqueried points count as neighbours, across the faces too; bad counts are refused.
TEST(PeriodicNeighbours, OfFirstSearchesThePointsAfterTheFirst) {
  PointSet p{2, {0.01, 0.5, 0.5, 0.1, 0.98, 0.5}, Box{0.0, 1.0}};
  const auto d = periodic_nearest_neighbour_distances_of_first(p, 1, 1);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_NEAR(d[0], 0.03, 1e-12);
  EXPECT_THROW(periodic_nearest_neighbour_distances_of_first(p, 4, 1), std::invalid_argument);
  EXPECT_THROW(periodic_nearest_neighbour_distances_of_first(PointSet{2, {0.5, 0.5}, Box{0.0, 1.0}}, 0, 1), std::invalid_argument);
}

// On the torus uniform random points give g(r) = 1 without any edge correction; each bin is compared
// with its Poisson standard error (every pair counted twice).
TEST(PeriodicRdf, UniformRandomPointsGiveOne) {
  for (int dimension : {2, 4, 6}) {
    PointSet p = uniform_random_points(dimension, 20000, Box{0.0, 1.0}, 3 + dimension, 2);
    p.domain = Domain::unit(DomainKind::torus);  // the torus' RDF: minimum-image pairs, no edge correction
    RdfOptions o;
    o.bins = 10;
    o.max_queries = 3000;
    o.r_max = dimension == 2 ? 0.05 : (dimension == 4 ? 0.2 : 0.3);
    const RdfCurve c = radial_distribution(p, o, 1, 2);
    const double volume = 1.0;
    for (std::size_t k = 0; k < c.g.size(); ++k) {
      const double lo = static_cast<double>(k) * o.r_max / o.bins, hi = static_cast<double>(k + 1) * o.r_max / o.bins;
      const double shell = unit_ball_volume(dimension) * (std::pow(hi, dimension) - std::pow(lo, dimension));
      const double expected_pairs = static_cast<double>(c.queries) * static_cast<double>(p.size() - 1) * shell / volume;
      const double standard_error = std::sqrt(2.0 / expected_pairs);
      EXPECT_NEAR(c.g[k], 1.0, 5.0 * standard_error + 1e-3) << dimension << "D bin " << k;
    }
  }
}

TEST(PeriodicRdf, RefusesReachesOfHalfTheSide) {
  PointSet p = uniform_random_points(3, 500, Box{0.0, 1.0}, 5, 1);
  p.domain = Domain::unit(DomainKind::torus);
  RdfOptions o;
  o.r_max = 0.5;
  EXPECT_THROW(radial_distribution(p, o, 1, 1), std::invalid_argument);
  o.r_max = 0.0;  // the default reach is capped below half the side
  EXPECT_LT(radial_distribution(p, o, 1, 1).r_max, 0.5);
}

}  // namespace
}  // namespace dfvn
