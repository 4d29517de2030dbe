// Reduced reproductions of Table 1 (3D-4D) and Table 2 (a small image), asserting the paper's points.
#include "reproduce/reproduce.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "reproduce/paper_tables.hpp"

namespace dfvn {
namespace {

const MethodResult& find(const std::vector<MethodResult>& results, Method m) {
  for (const auto& r : results)
    if (r.plan.method == m) return r;
  throw std::logic_error("method missing");
}

TEST(ReproduceTable1, JitterSobolAndPdsMatchThePaperIn3DAnd4D) {
  Table1Config config;
  config.dimensions = {3, 4};
  const Table1Result result = run_table1(config);
  ASSERT_EQ(result.results.size(), 2u);
  for (std::size_t d = 0; d < 2; ++d) {
    const int n = result.configs[d].dimension;
    for (Method m : {Method::jitter, Method::sobol, Method::pds}) {
      const double ours = find(result.results[d], m).nearest.median;
      const double paper = paper_table1_cell(n, m)->nn_median;
      std::printf("%dD %s median %.4f, paper %.3f (%+.1f%%)\n", n, to_string(m).data(), ours, paper, 100 * (ours / paper - 1));
      EXPECT_NEAR(ours / paper, 1.0, 0.05) << n << "D " << to_string(m);
    }
    EXPECT_GE(find(result.results[d], Method::pds).nearest.min, 0.1) << n << "D";
    EXPECT_TRUE(find(result.results[d], Method::cnj).rdf.has_value());
  }
  const std::string md = table1_markdown(result);
  EXPECT_NE(md.find("paper 0.069 (0.015):1"), std::string::npos) << "the paper's 3D jitter cell is shown";
  EXPECT_NE(md.find("Ours keeps min >= r = 0.1 in every dimension."), std::string::npos);

  config.out_dir = (std::filesystem::temp_directory_path() / "dfvn_test_table1").string();
  std::filesystem::create_directories(config.out_dir);
  write_table1(config, result, [](const std::string& line) { std::printf("%s\n", line.c_str()); });
  for (const char* name : {"table1.csv", "rdf.csv", "table1.md"})
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(config.out_dir) / name)) << name;
  std::filesystem::remove_all(config.out_dir);
}

TEST(ReproduceTable2, ThePapersConclusionsHoldOnASmallImage) {
  WarpConfig config;
  config.width = 96;
  config.height = 54;
  const Table2Result result = run_table2(config);
  ASSERT_EQ(result.rows.size(), 12u);
  for (const auto& row : result.rows)
    std::printf("%-18s RMSE %8.3f  evaluations/pixel %6.0f\n", row.variant.label().c_str(), row.rmse,
                static_cast<double>(row.field_evaluations) / (96 * 54));
  const Table2Conclusions c = table2_conclusions(result);
  EXPECT_TRUE(c.rk4_beats_euler);
  EXPECT_TRUE(c.reprojection_lowers_rmse);
  // Speed through the deterministic work count (timed assertions belong to benchmarks).
  EXPECT_TRUE(c.rk4_64_reproject_does_less_work);
  const auto& rows = result.rows;
  const auto rk4_64_1 = std::find_if(rows.begin(), rows.end(), [](const Table2Row& r) {
    return r.variant.integrator == Integrator::rk4 && r.variant.steps == 64 && r.variant.newton_steps == 1;
  });
  const auto euler_512 = std::find_if(rows.begin(), rows.end(), [](const Table2Row& r) {
    return r.variant.integrator == Integrator::euler && r.variant.steps == 512 && r.variant.newton_steps == 0;
  });
  EXPECT_LT(rk4_64_1->rmse, euler_512->rmse);
}

}  // namespace
}  // namespace dfvn
