#include "dfvn/reproduce/integration.hpp"

#include <gtest/gtest.h>

#include <string>

namespace dfvn {
namespace {

TEST(Integration, GridsSpanTheSizesWithoutRepeats) {
  EXPECT_EQ(integration_grids(3, 1u << 15), (std::vector<int>{4, 7, 11, 19, 32}));
  EXPECT_EQ(integration_grids(7, 1u << 15), (std::vector<int>{2, 3, 4}));
  EXPECT_EQ(integration_grids(6, 64), (std::vector<int>{2}));
}

// Uniform random points converge like n^-1/2 and Sobol points faster; seeds 1..16.
TEST(Integration, RandomConvergesAtTheMonteCarloRateAndSobolFaster) {
  IntegrationConfig config;
  config.dimensions = {3};
  config.realizations = 16;
  config.max_points = 4096;
  config.methods = {Method::random, Method::sobol};
  const IntegrationResult result = run_integration(config);
  ASSERT_EQ(result.cells.size(), 5u * 6u * 2u);
  for (const auto& s : result.slopes) {
    if (s.family == GenzFamily::discontinuous) continue;  // a jump: Sobol's rate drops towards n^-1/2 - 1/(2N)
    ASSERT_TRUE(s.slope.has_value());
    if (s.method == Method::random) {
      EXPECT_NEAR(*s.slope, -0.5, 0.25) << to_string(s.family);
    } else {
      EXPECT_LT(*s.slope, -0.8) << to_string(s.family);
    }
  }
}

std::string validation_error(const IntegrationConfig& config) {
  try {
    config.validate();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

// Issue 23: --methods cnj,cnj ran twice; --dims 3,7 --max-points 64 silently used 128 points in 7D.
TEST(Integration, RepeatsAndSizesBelowTheSmallestLatticeAreRefused) {
  IntegrationConfig config;
  config.methods = {Method::cnj, Method::cnj};
  EXPECT_EQ(validation_error(config), "--methods names 'cnj' twice");
  config.methods = {Method::cnj};
  config.dimensions = {3, 7};
  config.max_points = 64;
  EXPECT_EQ(validation_error(config),
            "--max-points 64 is below the smallest lattice of 7D, 2^7 = 128 points; give at least 128 or leave 7D out of --dims");
  config.max_points = 128;
  EXPECT_EQ(validation_error(config), "accepted");
  EXPECT_EQ(integration_grids(7, 128), (std::vector<int>{2}));
}

// Issue 23: one size gives no slope (it was written 0.0000), and the reading names only what was run:
// with cnj and random, nothing about jitter's errors; the methods' notes only for methods that ran.
TEST(Integration, TheReadingNamesOnlyWhatWasRun) {
  IntegrationConfig config;
  config.dimensions = {3};
  config.realizations = 2;
  config.max_points = 64;  // 3D: K = 4 only
  config.methods = {Method::cnj, Method::random};
  const IntegrationResult result = run_integration(config);
  ASSERT_FALSE(result.slopes.empty());
  for (const auto& s : result.slopes) EXPECT_FALSE(s.slope.has_value()) << to_string(s.method);
  const std::string md = integration_markdown(result);
  EXPECT_NE(md.find("(slope n/a)"), std::string::npos);
  EXPECT_EQ(md.find("slope 0.00"), std::string::npos);
  for (const char* unrun : {"jitter's", "Why CNJ loses", "Sobol", "Poisson", "4D", "5D", "6D", "7D", "halton", "lhs"})
    EXPECT_EQ(md.find(unrun), std::string::npos) << unrun << " in:\n" << md;
  EXPECT_NE(md.find("Jitter was not run"), std::string::npos);
}

}  // namespace
}  // namespace dfvn
