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

// Rows of Joe and Kuo's new-joe-kuo-6.21201 as published (d s a m_1 .. m_s): dimensions 2-16, 1111 and the
// last, 21201, copied from their text file (https://web.maths.unsw.edu.au/~fkuo/sobol/); the compiled-in
// table must decode to them (tests/python/test_sobol_table.py compares every row with SciPy's copy).
TEST(Sobol, DirectionTableDecodesToJoeKuosRows) {
  const std::vector<std::vector<std::uint32_t>> published = {
      {2, 1, 0, 1},           {3, 2, 1, 1, 3},         {4, 3, 1, 1, 3, 1},       {5, 3, 2, 1, 1, 1},
      {6, 4, 1, 1, 1, 3, 3},  {7, 4, 4, 1, 3, 5, 13},  {8, 5, 2, 1, 1, 5, 5, 17}, {9, 5, 4, 1, 1, 5, 5, 5},
      {10, 5, 7, 1, 1, 7, 11, 19},  {11, 5, 11, 1, 1, 5, 1, 1},   {12, 5, 13, 1, 1, 1, 3, 11},
      {13, 5, 14, 1, 3, 5, 5, 31},  {14, 6, 1, 1, 3, 3, 9, 7, 49}, {15, 6, 13, 1, 1, 1, 15, 21, 21},
      {16, 6, 16, 1, 3, 1, 13, 27, 49},
      {1111, 13, 4094, 1, 1, 5, 15, 19, 1, 7, 211, 157, 603, 403, 1387, 1583},
      {21201, 18, 131059, 1, 1, 7, 11, 15, 7, 37, 239, 337, 245, 1557, 3681, 7357, 9639, 27367, 26869, 114603, 86317}};
  const std::vector<JoeKuoRow> rows = joe_kuo_rows(kSobolMaxDimensions);
  ASSERT_EQ(rows.size(), 21201u);
  EXPECT_EQ(rows[0].degree, 0);  // dimension 1: van der Corput
  for (const auto& row : published) {
    const JoeKuoRow& got = rows[row[0] - 1];
    EXPECT_EQ(static_cast<std::uint32_t>(got.degree), row[1]) << "dimension " << row[0];
    EXPECT_EQ(got.coefficients, row[2]) << "dimension " << row[0];
    for (std::size_t k = 0; k < row[1]; ++k) EXPECT_EQ(got.initial[k], row[3 + k]) << "dimension " << row[0] << " m_" << k + 1;
  }
  EXPECT_NO_THROW(SobolSequence{kSobolMaxDimensions});
  EXPECT_THROW(SobolSequence{kSobolMaxDimensions + 1}, std::invalid_argument);
  EXPECT_THROW(joe_kuo_rows(0), std::invalid_argument);
}

// Coordinate j of a point never depends on the dimension: the first 15 columns of a 16D-40D set (the
// kernel for any dimension) are the 15D set (the unrolled kernels), scrambled or not, on both builds.
TEST(Sobol, HighDimensionsExtendTheUnrolledOnesColumnForColumn) {
  for (const Simd simd : {Simd::best, Simd::baseline})
    for (const Scramble scramble : {Scramble::owen, Scramble::none}) {
      const PointSet low = sobol_points(15, 5001, Box{-0.5, 3.0}, scramble, 8, 2, simd);
      for (int dim : {16, 21, 40}) {
        const PointSet high = sobol_points(dim, 5001, Box{-0.5, 3.0}, scramble, 8, 2, simd);
        for (std::size_t i = 0; i < 5001; ++i)
          for (int j = 0; j < 15; ++j)
            ASSERT_EQ(high.point(i)[j], low.point(i)[j]) << dim << "D " << to_string(scramble) << " point " << i << " coordinate " << j;
      }
    }
}

// The 64-digit sequence (Python's Sobol(bits=33..64)): unscrambled it is the 32-digit sequence's points
// below 2^32 (v_k over 64 bits is v_k over 32 bits times 2^32); it continues past 2^32; it refuses to
// pass 2^64 - 1.
TEST(Sobol, SixtyFourDigitsExtendTheSequence) {
  const PointSet narrow = sobol_points(6, 5000, Box{0.0, 1.0}, Scramble::none, 0, 2);
  EXPECT_EQ(sobol_points_64(6, 0, 5000, Box{0.0, 1.0}, Scramble::none, 0, 2).coordinates, narrow.coordinates);
  const std::uint64_t late = (std::uint64_t{1} << 32) - 3;
  EXPECT_EQ(sobol_points_64(6, late, 3, Box{0.0, 1.0}, Scramble::none, 0, 1).coordinates,
            sobol_points_range(6, late, 3, Box{0.0, 1.0}, Scramble::none, 0, 1).coordinates);
  // Point 2^32 + i: gray(2^32 + i) = gray(i) ^ 2^32 ^ 2^31 for i < 2^31, so its digits are point i's
  // XOR v_32 ^ v_31: other points than the first ones, still in [0, 1).
  const PointSet far = sobol_points_64(3, std::uint64_t{1} << 32, 8, Box{0.0, 1.0}, Scramble::none, 0, 1);
  const PointSet near = sobol_points_64(3, 0, 8, Box{0.0, 1.0}, Scramble::none, 0, 1);
  EXPECT_NE(far.coordinates, near.coordinates);
  for (double x : far.coordinates) EXPECT_TRUE(x >= 0.0 && x < 1.0);
  EXPECT_NO_THROW(sobol_points_64(2, ~std::uint64_t{0}, 1, Box{0.0, 1.0}, Scramble::owen, 1, 1));
  EXPECT_THROW(sobol_points_64(2, ~std::uint64_t{0}, 2, Box{0.0, 1.0}, Scramble::owen, 1, 1), std::invalid_argument);
  // The same bits on one and on two threads (2^18 points: enough coordinates for the second).
  EXPECT_EQ(sobol_points_64(4, 7, 1 << 18, Box{0.0, 1.0}, Scramble::owen, 3, 1).coordinates,
            sobol_points_64(4, 7, 1 << 18, Box{0.0, 1.0}, Scramble::owen, 3, 2).coordinates);
}

// The 64-digit scramble keeps the net structure too, and depends on the seed.
TEST(Sobol, SixtyFourDigitScramblingKeepsTheNetProperty) {
  const int m = 10;
  const std::size_t n = std::size_t{1} << m;
  for (std::uint64_t seed : {1ULL, 2ULL}) {
    const PointSet p = sobol_points_64(4, 0, n, Box{0.0, 1.0}, Scramble::owen, seed, 1);
    for (int j = 0; j < 4; ++j) {
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
  EXPECT_NE(sobol_points_64(3, 0, 64, Box{0.0, 1.0}, Scramble::owen, 1, 1).coordinates,
            sobol_points_64(3, 0, 64, Box{0.0, 1.0}, Scramble::owen, 2, 1).coordinates);
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

// The vectorised generator against the scalar definitions, for the unrolled dimensions and two above,
// past the first block of 4096 points: unscrambled coordinates are digits() / 2^32, and the top 32 bits
// of every scrambled coordinate are owen_scramble() of the point's digits.
TEST(Sobol, PointsEqualTheScalarDefinitions) {
  for (int dim : {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 23}) {
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

// AVX2 and SSE2 builds of the generator give the same bits, in the unrolled dimensions and above, scrambled
// or not, on the unit cube (where the AVX2 Owen kernel skips lo + side u) and on another domain. Without
// AVX2 both calls run the SSE2 build: the test is skipped.
TEST(Sobol, SimdPathsGiveTheSameBits) {
  if (!cpu_has_avx2()) GTEST_SKIP() << "this CPU has no AVX2 build: one build only";
  for (const Box box : {Box{-0.5, 3.0}, Box{0.0, 1.0}})
    for (int dim : {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 20, 33})
      for (const Scramble scramble : {Scramble::owen, Scramble::none}) {
        const PointSet best = sobol_points(dim, 20011, box, scramble, 11, 2, Simd::best);
        const PointSet baseline = sobol_points(dim, 20011, box, scramble, 11, 2, Simd::baseline);
        EXPECT_EQ(best.coordinates, baseline.coordinates)
            << "dimension " << dim << " " << to_string(scramble) << " on [" << box.lo << ", " << box.lo + box.side << ")";
      }
}

}  // namespace
}  // namespace dfvn
