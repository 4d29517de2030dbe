#include "sampling/sobol.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

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

TEST(Sobol, ScramblingDependsOnTheSeedOnlyAndNotOnThreads) {
  const PointSet a = sobol_points(5, 4096, Box{0.0, 0.7}, Scramble::owen, 9, 1);
  const PointSet b = sobol_points(5, 4096, Box{0.0, 0.7}, Scramble::owen, 9, 2);
  const PointSet c = sobol_points(5, 4096, Box{0.0, 0.7}, Scramble::owen, 10, 2);
  EXPECT_EQ(a.coordinates, b.coordinates);
  EXPECT_NE(a.coordinates, c.coordinates);
  for (double x : a.coordinates) {
    EXPECT_GE(x, 0.0);
    EXPECT_LT(x, 0.7);
  }
}

}  // namespace
}  // namespace dfvn
