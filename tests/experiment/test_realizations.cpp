#include "dfvn/experiment/realizations.hpp"

#include <gtest/gtest.h>

#include "dfvn/io/csv.hpp"
#include "dfvn/experiment/json_report.hpp"

#include <cmath>

#include "dfvn/stats/point_set_statistics.hpp"

namespace dfvn {
namespace {

TEST(Realizations, MeanAndSampleStandardDeviation) {
  const MeanSd s = mean_sd({1.0, 2.0, 3.0, 4.0});
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.sd, std::sqrt(5.0 / 3.0));
  EXPECT_EQ(mean_sd({7.0}).sd, 0.0);
}

// Issue 24: the summary rows keep every column's type. The label (seed) is empty, the word column
// stat says mean or sd, reals get their mean and sd as reals ("0.25", "0.0"), and integer columns
// (counts: their mean need not be an integer) and words stay empty.
TEST(Realizations, SummaryRowsPerGroup) {
  const std::string header = "method,points,nn_min,side,seed,notes,stat";
  const std::vector<std::string> rows = {"cnj,10,0.5,1.0,1,\"a b\",value", "pds,8,0.25,1.0,1,\"x\",value",
                                         "cnj,12,0.7,1.0,2,\"c\",value", "pds,8,0.25,1.0,2,\"y\",value"};
  EXPECT_EQ(realization_summary_rows(header, rows, {"method"}, "seed"),
            "cnj,,0.6,1.0,,,mean\n"
            "cnj,,0.141421356,0.0,,,sd\n"
            "pds,,0.25,1.0,,,mean\n"
            "pds,,0.0,0.0,,,sd\n");
  // A column that is empty or not a real in some row of a group has no mean there.
  EXPECT_EQ(realization_summary_rows("method,g,seed,stat", {"a,0.5,1,value", "a,,2,value"}, {"method"}, "seed"),
            "a,,,mean\na,,,sd\n");
  EXPECT_THROW(realization_summary_rows("method,g,seed", {"a,0.5,1"}, {"method"}, "seed"), std::invalid_argument)
      << "no stat column";
}

TEST(PointSetStatistics, OneDimensionalNearestNeighboursBySorting) {
  const PointSet points{1, {0.9, 0.1, 0.15, 0.5}, Box{}};
  const auto d = nearest_neighbour_distances_any_dimension(points, KnnBackend::nanoflann, 1);
  EXPECT_NEAR(d[0], 0.4, 1e-15);
  EXPECT_NEAR(d[1], 0.05, 1e-15);
  EXPECT_NEAR(d[2], 0.05, 1e-15);
  EXPECT_NEAR(d[3], 0.35, 1e-15);
}

TEST(PointSetStatistics, RejectsPointsOutsideTheDomain) {
  EXPECT_THROW(check_point_set(PointSet{2, {0.1, 0.2, 0.3, 1.2}, Box{0.0, 1.0}}), std::invalid_argument);
  EXPECT_NO_THROW(check_point_set(PointSet{2, {0.1, 0.2, 0.3, 1.2}, Box{0.0, 2.0}}));
  EXPECT_THROW(check_point_set(PointSet{2, {0.1, 0.2}, Box{0.0, 1.0}}), std::invalid_argument);
}

// Issue 23: an input named q"uo.csv was written into the CSV unescaped, and a name with the byte 0xFF
// made the JSON writer throw its own exception text.
TEST(PointSetStatistics, OddFileNamesAreEscapedInCsvAndJson) {
  const PointSet points{2, {0.1, 0.2, 0.6, 0.7}, Box{0.0, 1.0}};
  const PointSetStatistics statistics = measure_point_set(points, {});
  const std::string row = point_statistics_csv_row("a \"b\", c.csv", "0", points, statistics, false);
  EXPECT_EQ(row.substr(0, 17), "\"a \"\"b\"\", c.csv\",");
  const std::string header = point_statistics_csv_header();
  const std::string summary = realization_summary_rows(header.substr(0, header.size() - 1),
                                                       {row.substr(0, row.size() - 1), row.substr(0, row.size() - 1)},
                                                       {"input", "dim"}, "set");
  EXPECT_EQ(summary.substr(0, 17), "\"a \"\"b\"\", c.csv\",") << "the quoted name splits as one field";
  EXPECT_EQ(csv_quoted(""), "\"\"");
  EXPECT_EQ(csv_quoted("x\ny"), "\"x\ny\"");
  PointStatisticsRun run{"odd\xFF.csv", "csv", 1.0, {}, {statistics}, {2}, false};
  std::string json;
  ASSERT_NO_THROW(json = point_statistics_json(run));
  EXPECT_NE(json.find("\"input\": \"odd\xEF\xBF\xBD.csv\""), std::string::npos) << json;  // U+FFFD
}

}  // namespace
}  // namespace dfvn
