#include "dfvn/stats/nearest_neighbour.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "dfvn/core/dimension.hpp"
#include "dfvn/core/simd.hpp"
#include "dfvn/sampling/jitter.hpp"
#include "dfvn/sampling/lattice.hpp"
#include "dfvn/sampling/poisson_disk.hpp"
#include "dfvn/stats/nearest_other.hpp"

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
  const LatticeSpec l{3, 10, Protocol::fair};
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

// The summary selects its order statistics (nth_element): the same bits as reading them off a full sort,
// for every count from 1 to 300, with many ties and in shuffled orders.
TEST(NearestNeighbour, SummarySelectsWhatASortGives) {
  std::mt19937_64 rng(5);
  for (std::size_t n = 1; n <= 300; ++n) {
    std::vector<double> d(n);
    for (double& v : d) v = static_cast<double>(rng() % 17) * 0.125 + (rng() % 3 == 0 ? 1e-3 * static_cast<double>(rng() % 5) : 0.0);
    std::vector<double> sorted = d;
    std::sort(sorted.begin(), sorted.end());
    double sum = 0.0;
    for (double v : d) sum += v;
    const auto expected = summarize_nearest_neighbours(n, sum, [&](std::uint64_t k) { return sorted[k]; }, 2.0, 3);
    const auto got = summarize_nearest_neighbours(d, 2.0, 3);
    EXPECT_EQ(got.points, expected.points);
    EXPECT_EQ(got.min, expected.min) << n;
    EXPECT_EQ(got.q01, expected.q01) << n;
    EXPECT_EQ(got.median, expected.median) << n;
    EXPECT_EQ(got.mean, expected.mean) << n;
    EXPECT_EQ(got.median_scaled, expected.median_scaled) << n;
  }
}

TEST(NearestNeighbour, IndependentOfThreads) {
  const PointSet p = uniform_random_points(6, 20000, Box{0.0, 1.0}, 8, 2);
  EXPECT_EQ(nearest_neighbour_distances(p, KnnBackend::nanoflann, 1), nearest_neighbour_distances(p, KnnBackend::nanoflann, 2));
  EXPECT_EQ(nearest_neighbour_distances(p, KnnBackend::flann, 1), nearest_neighbour_distances(p, KnnBackend::flann, 2));
}


// The nanoflann backend's search (stats/nearest_other.hpp) against brute force, to the last bit, on sets
// made to tie and to collapse the tree: a lattice with exact ties in every direction, the same lattice
// with a jitter below its spacing, one point repeated, two and three points, and clusters 1e-9 wide.
TEST(NearestNeighbour, SearchEqualsBruteForceOnTiesAndDegenerateSets) {
  const auto check = [](const PointSet& p, const std::string& what) {
    const auto brute = nearest_neighbour_distances_brute_force(p);
    for (int threads : {1, 2}) {
      const auto nano = nearest_neighbour_distances(p, KnnBackend::nanoflann, threads);
      ASSERT_EQ(nano.size(), brute.size()) << what;
      for (std::size_t i = 0; i < brute.size(); ++i) ASSERT_EQ(nano[i], brute[i]) << what << " point " << i;
    }
  };
  for (int dimension : {2, 3, 5, 7}) {
    const int side = dimension == 7 ? 4 : dimension == 5 ? 6 : dimension == 3 ? 14 : 40;
    const LatticeSpec l{dimension, side, Protocol::fair};
    PointSet lattice{dimension, Coordinates(l.point_count() * static_cast<std::size_t>(dimension), 0.0), Box{0.0, 1.0}};
    for (std::uint64_t i = 0; i < l.point_count(); ++i) l.point(i, lattice.coordinates.data() + static_cast<std::size_t>(dimension) * i);
    check(lattice, std::to_string(dimension) + "D lattice");
    PointSet jittered = lattice;
    const PointSet noise = uniform_random_points(dimension, l.point_count(), Box{0.0, 1.0}, 7, 1);
    for (std::size_t k = 0; k < jittered.coordinates.size(); ++k)
      jittered.coordinates[k] = std::clamp(jittered.coordinates[k] + 0.3 / static_cast<double>(side) * (noise.coordinates[k] - 0.5), 0.0, 1.0);
    check(jittered, std::to_string(dimension) + "D jittered lattice");
    PointSet same{dimension, {}, Box{0.0, 1.0}};
    for (int k = 0; k < 100; ++k) same.coordinates.insert(same.coordinates.end(), lattice.point(3), lattice.point(3) + dimension);
    check(same, std::to_string(dimension) + "D repeated point");
    check(PointSet{dimension, Coordinates(lattice.point(0), lattice.point(2)), Box{0.0, 1.0}}, std::to_string(dimension) + "D two points");
    check(PointSet{dimension, Coordinates(lattice.point(5), lattice.point(8)), Box{0.0, 1.0}}, std::to_string(dimension) + "D three points");
    PointSet clusters = uniform_random_points(dimension, 2000, Box{0.0, 1.0}, 11, 1);
    for (std::size_t k = 0; k < clusters.coordinates.size(); ++k)
      clusters.coordinates[k] = static_cast<double>((k / static_cast<std::size_t>(dimension)) % 4) * 0.25 + 1e-9 * clusters.coordinates[k];
    check(clusters, std::to_string(dimension) + "D clusters");
  }
}

// The nearest distance of every point by one build of the search, over a tree with leaves of up to `leaf`.
template <int N, int Lanes>
std::vector<double> search_distances(const PointSet& p, nearest_other::NearestRows<N, Lanes> rows, int leaf) {
  const std::vector<std::uint32_t> nearest = nearest_other::nearest_of_every_point<N, Lanes>(p, rows, leaf);
  std::vector<double> distances(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_NE(nearest[i], i);
    distances[i] = distance_between(p, i, nearest[i]);
  }
  return distances;
}

// Every build of the search this CPU runs (x86-64 baseline; AVX2, four points to a block; AVX-512, eight),
// over trees with leaves of up to 10 and kLeafSize points: the same distances as brute
// force, bit for bit, on random points with duplicates and on a lattice with exact ties; on 20,000 random
// points, the same distances as the baseline build. And with_kernel picks the widest build the CPU runs.
TEST(NearestNeighbour, SearchBuildsAgree) {
  for (int dimension = 2; dimension <= 8; ++dimension) {
    PointSet small = uniform_random_points(dimension, 2500, Box{0.0, 1.0}, 60 + dimension, 1);
    for (int k = 0; k < 5; ++k) small.coordinates.insert(small.coordinates.end(), small.point(k * 13), small.point(k * 13) + dimension);
    const int side = dimension >= 7 ? 3 : dimension == 6 ? 4 : dimension == 5 ? 5 : dimension == 4 ? 7 : dimension == 3 ? 12 : 40;
    const LatticeSpec l{dimension, side, Protocol::fair};
    PointSet lattice{dimension, Coordinates(l.point_count() * static_cast<std::size_t>(dimension), 0.0), Box{0.0, 1.0}};
    for (std::uint64_t i = 0; i < l.point_count(); ++i) l.point(i, lattice.coordinates.data() + static_cast<std::size_t>(dimension) * i);
    const PointSet large = uniform_random_points(dimension, 20000, Box{0.0, 1.0}, 40 + dimension, 1);
    dispatch_dimension(dimension, [&]<int N>() {
      const auto every_build = [&](const PointSet& p, const std::vector<double>& expected, const std::string& what) {
        for (const int leaf : {10, nearest_other::kLeafSize}) {
          EXPECT_EQ((search_distances<N, 4>(p, &nearest_other::baseline::nearest_rows<N, false>, leaf)), expected) << N << "D " << what << " baseline, leaf " << leaf;
#if defined(__x86_64__)
          if (cpu_has_avx2()) {
            EXPECT_EQ((search_distances<N, 4>(p, &nearest_other::avx2::nearest_rows<N, false>, leaf)), expected) << N << "D " << what << " AVX2, leaf " << leaf;
          }
#endif
        }
#if defined(__x86_64__)
        if (cpu_has_avx512()) {
          for (const int leaf : {10, nearest_other::kLeafSize})
            EXPECT_EQ((search_distances<N, 8>(p, &nearest_other::avx512::nearest_rows<N, false>, leaf)), expected) << N << "D " << what << " AVX-512, leaf " << leaf;
        }
#endif
      };
      every_build(small, nearest_neighbour_distances_brute_force(small), "random points with duplicates");
      every_build(lattice, nearest_neighbour_distances_brute_force(lattice), "lattice");
      every_build(large, search_distances<N, 4>(large, &nearest_other::baseline::nearest_rows<N, false>, 64), "20,000 random points");
      const int lanes = nearest_other::with_kernel<N>(Simd::best, []<int Lanes>(nearest_other::Kernel<N, Lanes>) { return Lanes; });
      EXPECT_EQ(lanes, cpu_has_avx512() ? 8 : 4);
      const bool baseline = nearest_other::with_kernel<N>(Simd::best, []<int Lanes>(nearest_other::Kernel<N, Lanes> k) {
        if constexpr (Lanes == 4) return k.rows == &nearest_other::baseline::nearest_rows<N, false>;
        return false;
      });
      EXPECT_EQ(baseline, !cpu_has_avx2() && !cpu_has_avx512());
      nearest_other::with_kernel<N>(Simd::baseline, []<int Lanes>(nearest_other::Kernel<N, Lanes> k) {
        if constexpr (Lanes == 4) EXPECT_EQ(k.rows, (&nearest_other::baseline::nearest_rows<N, false>));
        else ADD_FAILURE() << "Simd::baseline gave an 8-lane build";
      });
    });
  }
}

// rows_within in every build (the RDF's pair search): the rows within a radius of a query point, each at the
// squared distance brute force sums (axes in order), the coordinates handed over those of the row, and no other
// row; 2D-8D, random points with duplicates, queries at points of the set and off it, radii of 1-3 spacings.
TEST(NearestNeighbour, RowsWithinEqualsBruteForceInEveryBuild) {
  for (int dimension = 2; dimension <= 8; ++dimension) {
    PointSet p = uniform_random_points(dimension, 3000, Box{0.0, 1.0}, 80 + dimension, 1);
    for (int k = 0; k < 5; ++k) p.coordinates.insert(p.coordinates.end(), p.point(k * 17), p.point(k * 17) + dimension);
    const PointSet queries = uniform_random_points(dimension, 20, Box{-0.1, 1.2}, 90 + dimension, 1);
    const double spacing = std::pow(1.0 / static_cast<double>(p.size()), 1.0 / dimension);
    dispatch_dimension(dimension, [&]<int N>() {
      const PointSetAdaptor<N> adaptor{p};
      const KdTree<N> tree(N, adaptor, kd_tree_params(nearest_other::kLeafSize));
      const auto check = [&]<int Lanes>(std::integral_constant<int, Lanes>, auto rows_within, const char* build) {
        const nearest_other::Index<N, Lanes> index(p, tree);
        nearest_other::Scratch<N> scratch = nearest_other::make_scratch(index);
        for (std::size_t k = 0; k < 40; ++k) {
          const double* q = k < 20 ? p.point(k * 41) : queries.point(k - 20);
          const double search2 = std::pow((1.0 + static_cast<double>(k % 3)) * spacing, 2);
          std::vector<std::pair<std::uint32_t, double>> found, expected;
          rows_within(index, q, search2, scratch, [&](std::uint32_t row, double dist2, const double* block, int lane) {
            const std::uint32_t j = index.original()[row];
            for (int a = 0; a < N; ++a) EXPECT_EQ(block[Lanes * a + lane], p.point(j)[a]) << N << "D " << build;
            found.emplace_back(j, dist2);
          });
          for (std::size_t j = 0; j < p.size(); ++j) {
            double dist2 = 0.0;
            for (int a = 0; a < N; ++a) dist2 += (p.point(j)[a] - q[a]) * (p.point(j)[a] - q[a]);
            if (dist2 <= search2) expected.emplace_back(static_cast<std::uint32_t>(j), dist2);
          }
          std::sort(found.begin(), found.end());
          EXPECT_EQ(found, expected) << N << "D " << build << " query " << k;
        }
      };
      check(std::integral_constant<int, 4>{}, [](const auto& index, const double* q, double search2, auto& s, auto&& visit) {
        nearest_other::baseline::rows_within<N>(index, q, search2, s, visit);
      }, "baseline");
#if defined(__x86_64__)
      if (cpu_has_avx2())
        check(std::integral_constant<int, 4>{}, [](const auto& index, const double* q, double search2, auto& s, auto&& visit) {
          nearest_other::avx2::rows_within<N>(index, q, search2, s, visit);
        }, "AVX2");
      if (cpu_has_avx512())
        check(std::integral_constant<int, 8>{}, [](const auto& index, const double* q, double search2, auto& s, auto&& visit) {
          nearest_other::avx512::rows_within<N>(index, q, search2, s, visit);
        }, "AVX-512");
#endif
      const int lanes = nearest_other::with_rows_within<N>(Simd::best, []<int Lanes>(std::integral_constant<int, Lanes>, auto) { return Lanes; });
      EXPECT_EQ(lanes, cpu_has_avx512() ? 8 : 4);
    });
  }
}

// A set of random points and a lattice with exact ties (every neighbour at one spacing, several per point),
// both with a few duplicates, shuffled so that the first q are no region of their own.
PointSet of_first_set(int dimension, bool lattice, std::uint64_t seed) {
  PointSet p{dimension, {}, Box{0.0, 1.0}};
  if (lattice) {
    const int side = dimension >= 7 ? 3 : dimension == 6 ? 4 : dimension == 5 ? 5 : dimension == 4 ? 7 : dimension == 3 ? 12 : 40;
    const LatticeSpec l{dimension, side, Protocol::fair};
    p.coordinates.resize(l.point_count() * static_cast<std::size_t>(dimension));
    for (std::uint64_t i = 0; i < l.point_count(); ++i) l.point(i, p.coordinates.data() + static_cast<std::size_t>(dimension) * i);
  } else {
    p = uniform_random_points(dimension, 1500, Box{0.0, 1.0}, seed, 1);
  }
  for (int k = 0; k < 3; ++k) p.coordinates.insert(p.coordinates.end(), p.point(k * 11), p.point(k * 11) + dimension);
  // A fixed shuffle (Fisher-Yates on a hash), rows swapped whole.
  const std::size_t n = p.size();
  for (std::size_t i = n - 1; i > 0; --i) {
    const std::size_t j = (i * 2654435761u + seed * 40503u) % (i + 1);
    std::swap_ranges(p.coordinates.data() + i * static_cast<std::size_t>(dimension), p.coordinates.data() + (i + 1) * static_cast<std::size_t>(dimension),
                     p.coordinates.data() + j * static_cast<std::size_t>(dimension));
  }
  return p;
}

// nearest_neighbour_distances_of_first(points, q): the first q values of the full function, to the bit, and
// brute force's; for q = 0, 1, a middle count and n, both backends, 1 and 2 threads, 2D-8D, random and
// lattice sets with ties and duplicates.
TEST(NearestNeighbour, OfFirstEqualsTheFullFunctionAndBruteForce) {
  for (int dimension = 2; dimension <= 8; ++dimension)
    for (bool lattice : {false, true}) {
      const PointSet p = of_first_set(dimension, lattice, 60 + static_cast<std::uint64_t>(dimension));
      const auto brute = nearest_neighbour_distances_brute_force(p);
      for (KnnBackend backend : {KnnBackend::nanoflann, KnnBackend::flann}) {
        const auto full = nearest_neighbour_distances(p, backend, 2);
        ASSERT_EQ(full, brute);
        for (std::size_t q : {std::size_t{0}, std::size_t{1}, p.size() / 3, p.size() - 1, p.size()})
          for (int threads : {1, 2}) {
            if (threads == 1 && q != p.size() / 3) continue;  // one thread once: the answer is the same
            const auto first = nearest_neighbour_distances_of_first(p, q, backend, threads);
            ASSERT_EQ(first.size(), q);
            for (std::size_t i = 0; i < q; ++i)
              ASSERT_EQ(first[i], full[i]) << dimension << "D " << (lattice ? "lattice" : "random") << " "
                                           << to_string(backend) << " q = " << q << " point " << i;
          }
      }
    }
}

// The tree is over every point: a point's neighbour among the unqueried rows counts. Two points of a pair
// far from the rest, one queried and one not.
TEST(NearestNeighbour, OfFirstSearchesThePointsAfterTheFirst) {
  PointSet p{3, {0.5, 0.5, 0.5, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 0.5, 0.5, 0.25}, Box{0.0, 1.0}};
  for (KnnBackend backend : {KnnBackend::nanoflann, KnnBackend::flann}) {
    const auto d = nearest_neighbour_distances_of_first(p, 1, backend, 1);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0], 0.25);
  }
  EXPECT_THROW(nearest_neighbour_distances_of_first(p, 5, KnnBackend::nanoflann, 1), std::invalid_argument);
  EXPECT_THROW(nearest_neighbour_distances_of_first(PointSet{3, {0.5, 0.5, 0.5}, Box{0.0, 1.0}}, 1, KnnBackend::nanoflann, 1),
               std::invalid_argument);
}

}  // namespace
}  // namespace dfvn
