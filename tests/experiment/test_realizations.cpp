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

// The summary is a table of its own: per group and per column that holds a number in every row and
// varies (or is a statistic, nn_min, or a time), the mean, sample sd and standard error as reals; a constant
// column (a setting: side) is not summarised, nor are words, the label (seed) and a column empty in some row; integer counts that vary
// (points) are, their mean a real. A seconds column keeps 6 decimals.
TEST(Realizations, SummaryTablePerGroup) {
  const std::string header = "method,points,nn_min,side,seed,seconds_stats,notes";
  const std::vector<std::string> rows = {"cnj,10,0.5,1.0,1,0.100000,\"a b\"", "pds,8,0.25,1.0,1,0.100000,\"x\"",
                                         "cnj,12,0.7,1.0,2,0.300000,\"c\"", "pds,8,0.25,1.0,2,0.100000,\"y\""};
  EXPECT_EQ(realization_summary_csv(header, rows, {"method"}, "seed"),
            "method,statistic,realizations,mean,sd,standard_error\n"
            "cnj,points,2,11.0,1.41421356,1.0\n"
            "cnj,nn_min,2,0.6,0.141421356,0.1\n"
            "cnj,seconds_stats,2,0.200000,0.141421,0.100000\n"
            "pds,nn_min,2,0.25,0.0,0.0\n"
            "pds,seconds_stats,2,0.100000,0.000000,0.000000\n");
  // A statistic is summarised even when it does not vary; a constant setting is not.
  EXPECT_EQ(realization_summary_csv("method,nn_min,side,seed", {"a,0.5,1.0,1", "a,0.5,1.0,2"}, {"method"}, "seed"),
            "method,statistic,realizations,mean,sd,standard_error\na,nn_min,2,0.5,0.0,0.0\n");
  // A column that is empty or not a number in some row of a group has no summary there.
  EXPECT_EQ(realization_summary_csv("method,g,seed", {"a,0.5,1", "a,,2"}, {"method"}, "seed"),
            "method,statistic,realizations,mean,sd,standard_error\n");
  EXPECT_THROW(realization_summary_csv("method,g", {"a,0.5"}, {"method"}, "seed"), std::invalid_argument)
      << "no seed column";
  EXPECT_NEAR(standard_error(mean_sd({1.0, 3.0}), 2), 1.0, 1e-15);
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
  const std::string summary = realization_summary_csv(header.substr(0, header.size() - 1),
                                                      {row.substr(0, row.size() - 1), row.substr(0, row.size() - 1)},
                                                      {"input", "dim"}, "set");
  const std::string header_line = "input,dim,statistic,realizations,mean,sd,standard_error\n";
  ASSERT_EQ(summary.substr(0, header_line.size()), header_line);
  EXPECT_EQ(summary.substr(header_line.size(), 39), "\"a \"\"b\"\", c.csv\",2,nn_min,2,0.707106781") << summary
      << "the quoted name splits as one field";
  EXPECT_EQ(csv_quoted(""), "\"\"");
  EXPECT_EQ(csv_quoted("x\ny"), "\"x\ny\"");
  PointStatisticsRun run{"odd\xFF.csv", "csv", 1.0, {}, {statistics}, {2}, false};
  std::string json;
  ASSERT_NO_THROW(json = point_statistics_json(run));
  EXPECT_NE(json.find("\"input\": \"odd\xEF\xBF\xBD.csv\""), std::string::npos) << json;  // U+FFFD
}

}  // namespace
}  // namespace dfvn
