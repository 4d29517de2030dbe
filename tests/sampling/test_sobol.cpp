#include "dfvn/sampling/sobol.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "dfvn/core/parallel.hpp"

namespace dfvn {
namespace {

TEST(Sobol, UnscrambledPointsEqualScipyReference) {
  std::ifstream in(std::string(DFVN_TEST_DATA_DIR) + "/scipy_sobol_unscrambled_8d.csv");
  ASSERT_TRUE(in) << "missing reference data";
  std::vector<std::vector<double>> reference;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<double> row;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) row.push_back(std::stod(cell));
    reference.push_back(row);
  }
  ASSERT_EQ(reference.size(), 32u);
  const PointSet p = sobol_points(8, 32, Box{0.0, 1.0}, Scramble::none, 0, 1);
  for (std::size_t i = 0; i < 32; ++i)
    for (int j = 0; j < 8; ++j) EXPECT_EQ(p.point(i)[j], reference[i][j]) << "point " << i << " dim " << j;
}

TEST(Sobol, DirectionTableHasFifteenDimensions) {
  EXPECT_NO_THROW(SobolSequence(15));
  EXPECT_THROW(SobolSequence(16), std::invalid_argument);
}

// Owen scrambling keeps the net structure: with 2^m points every dimension has exactly one point in
// each interval [k 2^-m, (k+1) 2^-m), and dimensions 1-2 form a (0, m, 2)-net: one point in every
// elementary box of area 2^-m.
TEST(Sobol, OwenScramblingKeepsTheNetProperty) {
  const int m = 10;
  const std::size_t n = std::size_t{1} << m;
  for (std::uint64_t seed : {1ULL, 2ULL, 12345ULL}) {
    const PointSet p = sobol_points(8, n, Box{0.0, 1.0}, Scramble::owen, seed, 2);
    for (int j = 0; j < 8; ++j) {
      std::set<long> strata;
      for (std::size_t i = 0; i < n; ++i) strata.insert(static_cast<long>(p.point(i)[j] * n));
      EXPECT_EQ(strata.size(), n) << "dimension " << j << " seed " << seed;
    }
    for (int a = 0; a <= m; ++a) {
      std::set<std::pair<long, long>> boxes;
      for (std::size_t i = 0; i < n; ++i)
        boxes.insert({static_cast<long>(p.point(i)[0] * (1L << a)), static_cast<long>(p.point(i)[1] * (1L << (m - a)))});
      EXPECT_EQ(boxes.size(), n) << "boxes 2^-" << a << " x 2^-" << (m - a);
    }
  }
}

// 2^18 5D points: enough coordinates for sobol_points to use both threads (core/parallel.hpp).
TEST(Sobol, ScramblingDependsOnTheSeedOnlyAndNotOnThreads) {
  const PointSet a = sobol_points(5, 1 << 18, Box{0.0, 0.7}, Scramble::owen, 9, 1);
  const PointSet b = sobol_points(5, 1 << 18, Box{0.0, 0.7}, Scramble::owen, 9, 2);
  const PointSet c = sobol_points(5, 1 << 18, Box{0.0, 0.7}, Scramble::owen, 10, 2);
  ASSERT_TRUE(worth_threads(a.coordinates.size()));
  EXPECT_EQ(a.coordinates, b.coordinates);
  EXPECT_NE(a.coordinates, c.coordinates);
  for (double x : a.coordinates) {
    EXPECT_GE(x, 0.0);
    EXPECT_LT(x, 0.7);
  }
}

// The vectorised generator against the scalar definitions, for every dimension the table has and
// past the first block of 4096 points: unscrambled coordinates are digits() / 2^32, and the top 32 bits
// of every scrambled coordinate are owen_scramble() of the point's digits.
TEST(Sobol, PointsEqualTheScalarDefinitions) {
  for (int dim = 1; dim <= 15; ++dim) {
    const SobolSequence sequence(dim);
    const std::uint64_t count = 5001;  // more than one block of 4096, not a power of 2, nor a multiple of 2
    const PointSet plain = sobol_points(dim, count, Box{0.0, 1.0}, Scramble::none, 3, 2);
    const PointSet scrambled = sobol_points(dim, count, Box{0.0, 1.0}, Scramble::owen, 3, 2);
    for (std::uint64_t i = 0; i < count; i += 7)
      for (int j = 0; j < dim; ++j) {
        const std::uint32_t digits = sequence.digits(static_cast<std::uint32_t>(i), j);
        ASSERT_EQ(std::ldexp(plain.point(i)[j], 32), static_cast<double>(digits))
            << "dimension " << dim << " point " << i << " coordinate " << j;
        const auto top = static_cast<std::uint32_t>(std::ldexp(scrambled.point(i)[j], 32));
        ASSERT_EQ(top, owen_scramble(digits, 3, j)) << "dimension " << dim << " point " << i << " coordinate " << j;
      }
  }
}

// The random bits below the scrambled digits of coordinate j depend on the seed, the point and j only:
// the first coordinates of a 1D-4D and a 7D set are the same numbers.
TEST(Sobol, LowBitsDoNotDependOnTheDimension) {
  const PointSet large = sobol_points(7, 1001, Box{0.0, 1.0}, Scramble::owen, 5, 1);
  for (int dim = 1; dim <= 4; ++dim) {
    const PointSet small = sobol_points(dim, 1001, Box{0.0, 1.0}, Scramble::owen, 5, 1);
    for (std::size_t i = 0; i < 1001; ++i)
      for (int j = 0; j < dim; ++j)
        ASSERT_EQ(small.point(i)[j], large.point(i)[j]) << dim << "D point " << i << " coordinate " << j;
  }
}

// AVX2 and SSE2 builds of the generator give the same bits, in every dimension, scrambled or not, on a
// domain other than the unit cube. Without AVX2 both calls run the SSE2 build: the test is skipped.
TEST(Sobol, SimdPathsGiveTheSameBits) {
  if (!cpu_has_avx2()) GTEST_SKIP() << "this CPU has no AVX2 build: one build only";
  for (int dim = 1; dim <= 15; ++dim)
    for (const Scramble scramble : {Scramble::owen, Scramble::none}) {
      const PointSet best = sobol_points(dim, 20011, Box{-0.5, 3.0}, scramble, 11, 2, Simd::best);
      const PointSet baseline = sobol_points(dim, 20011, Box{-0.5, 3.0}, scramble, 11, 2, Simd::baseline);
      EXPECT_EQ(best.coordinates, baseline.coordinates) << "dimension " << dim << " " << to_string(scramble);
    }
}

}  // namespace
}  // namespace dfvn
