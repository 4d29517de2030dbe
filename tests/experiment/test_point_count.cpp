// Point counts instead of lattice sizes: grid_for_count and SampleConfig::count.
#include <cmath>

#include "dfvn/experiment/experiment.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

TEST(GridForCount, PicksTheLatticeNearestToTheCount) {
  EXPECT_EQ(grid_for_count(3, 1000), 10);
  EXPECT_EQ(grid_for_count(3, 40), 3);    // |27 - 40| = 13 < |64 - 40| = 24
  EXPECT_EQ(grid_for_count(3, 50), 4);    // |64 - 50| = 14 < |27 - 50| = 23
  EXPECT_EQ(grid_for_count(7, 279936), 6);  // 6^7 exactly
  EXPECT_EQ(grid_for_count(7, 279935), 6);
  EXPECT_EQ(grid_for_count(2, 1), 2);     // the smallest lattice
  EXPECT_EQ(grid_for_count(2, 12), 3);    // |9 - 12| = 3 < |16 - 12| = 4
  EXPECT_EQ(grid_for_count(2, 13), 4);    // |16 - 13| = 3 < |9 - 13| = 4
  EXPECT_EQ(grid_for_count(8, std::uint64_t{1} << 40), 32);
  // Against a brute-force search over K.
  for (int n = 2; n <= 8; ++n)
    for (std::uint64_t count : {3u, 77u, 500u, 4097u, 100000u, 2000000u}) {
      int best = 2;
      for (int k = 2; k < 2000; ++k)
        if (std::abs(std::pow(k, n) - double(count)) < std::abs(std::pow(best, n) - double(count))) best = k;
      EXPECT_EQ(grid_for_count(n, count), best) << n << "D, " << count;
    }
  EXPECT_THROW(grid_for_count(3, 0), std::invalid_argument);
  EXPECT_THROW(grid_for_count(0, 10), std::invalid_argument);
}

TEST(SampleCount, NonLatticeMethodsTakeExactlyTheCount) {
  SampleConfig config;
  config.dimension = 3;
  config.count = 1000;
  config.grid = grid_for_count(3, config.count);
  for (Method m : {Method::sobol, Method::random, Method::halton, Method::lhs, Method::pds})
    EXPECT_EQ(plan_method(config, m).requested, 1000u) << to_string(m);
  for (Method m : {Method::cnj, Method::jitter}) EXPECT_EQ(plan_method(config, m).requested, 1000u);  // 10^3
  config.count = 900;
  for (Method m : {Method::cnj, Method::jitter}) EXPECT_EQ(plan_method(config, m).requested, 1000u);
  EXPECT_EQ(sample_method(config, Method::lhs).points.size(), 900u);
  EXPECT_EQ(sample_method(config, Method::sobol).points.size(), 900u);
}

// sample_method gives the points run_sampling generates for the same configuration.
TEST(SampleCount, SampleMethodEqualsRunSampling) {
  SampleConfig config;
  config.dimension = 3;
  config.grid = 5;
  config.seed = 4;
  config.methods = {Method::cnj, Method::pds, Method::sobol};
  const auto results = run_sampling(config, true);
  for (const auto& r : results)
    EXPECT_EQ(sample_method(config, r.plan.method).points.coordinates, r.points.coordinates) << to_string(r.plan.method);
}

}  // namespace
}  // namespace dfvn
