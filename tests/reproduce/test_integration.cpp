#include "reproduce/integration.hpp"

#include <gtest/gtest.h>

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
    if (s.method == Method::random) {
      EXPECT_NEAR(s.slope, -0.5, 0.25) << to_string(s.family);
    } else {
      EXPECT_LT(s.slope, -0.8) << to_string(s.family);
    }
  }
}

}  // namespace
}  // namespace dfvn
