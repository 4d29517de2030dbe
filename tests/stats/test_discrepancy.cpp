#include "dfvn/stats/discrepancy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "dfvn/io/csv.hpp"
#include "dfvn/sampling/jitter.hpp"

namespace dfvn {
namespace {

PointSet read_set(const std::string& name, int dimension) {
  std::ifstream in(std::string(DFVN_TEST_DATA_DIR) + "/" + name);
  EXPECT_TRUE(in) << name;
  PointTable table = read_points_csv(in, dimension);
  return PointSet{dimension, std::move(table.coordinates), Box{0.0, 1.0}};
}

// Reference values: scipy.stats.qmc.discrepancy (SciPy 1.10.1, Debian python3-scipy) on the sets in
// tests/stats/data, made once by scripts/make_discrepancy_reference.py.
TEST(Discrepancy, EqualsScipyIn2DTo8D) {
  std::ifstream in(std::string(DFVN_TEST_DATA_DIR) + "/discrepancy_reference.csv");
  ASSERT_TRUE(in);
  std::string line;
  int checked = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("file,", 0) == 0) continue;
    std::istringstream row(line);
    std::string file, dim, count, method, value;
    std::getline(row, file, ',');
    std::getline(row, dim, ',');
    std::getline(row, count, ',');
    std::getline(row, method, ',');
    std::getline(row, value, ',');
    const PointSet points = read_set(file, std::stoi(dim));
    ASSERT_EQ(points.size(), std::stoul(count)) << file;
    const double expected = std::stod(value);
    const double ours = discrepancy(points, parse_discrepancy(method), 0);
    EXPECT_NEAR(ours, expected, 1e-10 * std::abs(expected)) << file << " " << method;
    ++checked;
  }
  EXPECT_EQ(checked, 7 * 2 * 4);  // dimensions 2..8, two sets each, four discrepancies
}

TEST(Discrepancy, SameBitsForAnyThreadCount) {
  for (int dimension : {1, 3, 8}) {
    const PointSet points = uniform_random_points(dimension, 1500, Box{0.0, 1.0}, 17, 0);
    for (DiscrepancyKind kind : kAllDiscrepancies) {
      const double one = discrepancy(points, kind, 1);
      for (int threads : {2, 3, 8}) EXPECT_EQ(one, discrepancy(points, kind, threads)) << to_string(kind) << " " << threads;
    }
  }
}

// One point at the centre of [0,1]: CD^2 = 13/12 - 2 + 1 = 1/12 by the closed form, and the L2-star
// discrepancy of {1/2} is sqrt(1/3 - (1 - 1/4) + 1/2) = sqrt(1/12).
TEST(Discrepancy, OnePointInOneDimensionByHand) {
  const PointSet centre{1, {0.5}, Box{0.0, 1.0}};
  EXPECT_NEAR(discrepancy(centre, DiscrepancyKind::centered, 1), 1.0 / 12.0, 1e-15);
  EXPECT_NEAR(discrepancy(centre, DiscrepancyKind::l2_star, 1), std::sqrt(1.0 / 12.0), 1e-15);
}

TEST(Discrepancy, MapsTheDomainAndRejectsPointsOutsideIt) {
  PointSet unit = uniform_random_points(3, 100, Box{0.0, 1.0}, 5, 1);
  PointSet scaled = unit;
  scaled.domain = Box{0.0, 2.0};
  for (double& x : scaled.coordinates) x *= 2.0;
  EXPECT_NEAR(discrepancy(unit, DiscrepancyKind::centered, 1), discrepancy(scaled, DiscrepancyKind::centered, 1), 1e-14);
  unit.coordinates[4] = 1.5;
  EXPECT_THROW(discrepancy(unit, DiscrepancyKind::centered, 1), std::invalid_argument);
  EXPECT_THROW(discrepancy(PointSet{3, {}, Box{}}, DiscrepancyKind::centered, 1), std::invalid_argument);
}

TEST(Discrepancy, ParsesScipyNames) {
  EXPECT_EQ(parse_discrepancy("L2-star"), DiscrepancyKind::l2_star);
  EXPECT_EQ(parse_discrepancy("wd"), DiscrepancyKind::wrap_around);
  EXPECT_THROW(parse_discrepancy("XX"), std::invalid_argument);
}

}  // namespace
}  // namespace dfvn
