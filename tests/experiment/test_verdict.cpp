// The main job's verdict (experiment/verdict.hpp): rankings, ratios, the two-standard-error rule, and a
// report that names only what ran and says where CNJ loses.
#include "dfvn/experiment/verdict.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace dfvn {
namespace {

MethodResult measured(Method m, double min, double median_scaled) {
  MethodResult r;
  r.plan.method = m;
  r.plan.domain = Domain::unit(DomainKind::torus);
  r.point_count = 512;
  r.measured = true;
  r.nearest.min = min;
  r.nearest.q01 = min * 1.5;
  r.nearest.median_scaled = median_scaled;
  return r;
}

TEST(Verdict, RanksEveryStatisticLargestFirst) {
  SampleConfig c;
  c.dimension = 3;
  c.grid = 8;
  const std::vector<SamplingRealization> runs{
      {1, {measured(Method::cnj, 0.04, 0.88), measured(Method::jitter_matched, 0.02, 0.77), measured(Method::pds, 0.16, 0.98)}}};
  const auto statistics = verdict_statistics(runs);
  ASSERT_EQ(statistics.size(), 3u);
  EXPECT_EQ(statistics[0].name, "nn_min");
  EXPECT_EQ(statistics[2].name, "nn_median_scaled");
  for (const auto& s : statistics) {
    ASSERT_EQ(s.ranked.size(), 3u);
    EXPECT_EQ(s.ranked[0].method, Method::pds);
    EXPECT_EQ(s.ranked[1].method, Method::cnj);
    EXPECT_EQ(s.ranked[2].method, Method::jitter_matched);
    EXPECT_EQ(s.ranked[0].standard_error, 0.0);  // one realization: no spread
  }
  const std::string md = verdict_markdown(c, runs);
  EXPECT_NE(md.find("| 1 | pds | 0.16 | 8x | 1x |"), std::string::npos) << md;
  EXPECT_NE(md.find("It loses to pds (0.25x of its value)"), std::string::npos) << md;
  EXPECT_NE(md.find("It beats jitter-matched (2x its value)"), std::string::npos) << md;
  EXPECT_NE(md.find("the seed-to-seed spread is unknown"), std::string::npos);
  EXPECT_NE(md.find("every set in the torus [0, 1)^3, measured with minimum-image distances, 512 points each"),
            std::string::npos)
      << md;
  EXPECT_EQ(md.find("sobol"), std::string::npos);  // only what ran
  EXPECT_EQ(md.find("s.e."), std::string::npos);
  const auto summary = verdict_summary(c, runs);
  ASSERT_EQ(summary.size(), 2u);
  EXPECT_EQ(summary[1],
            "verdict by nn_median_scaled (larger packs better): pds 0.98 > cnj 0.88 > jitter-matched 0.77; cnj is 2 of 3 "
            "(0.898x of pds's)");
}

// Means over realizations with their standard errors; a difference counts when it exceeds twice the
// standard error of the difference.
TEST(Verdict, TwoStandardErrorsDecideOverRealizations) {
  SampleConfig c;
  c.dimension = 3;
  c.grid = 8;
  std::vector<SamplingRealization> runs;
  const double cnj[] = {0.86, 0.88, 0.90}, matched[] = {0.76, 0.77, 0.78}, sobol[] = {0.80, 0.90, 1.00};
  for (int r = 0; r < 3; ++r)
    runs.push_back({static_cast<std::uint64_t>(r + 1),
                    {measured(Method::cnj, 0.04, cnj[r]), measured(Method::jitter_matched, 0.02, matched[r]),
                     measured(Method::sobol, 0.03, sobol[r])}});
  const VerdictStatistic s = verdict_statistics(runs)[2];
  ASSERT_EQ(s.ranked[0].method, Method::sobol);  // 0.90 against CNJ's 0.88
  EXPECT_NEAR(s.ranked[0].standard_error, 0.1 / std::sqrt(3.0), 1e-12);
  const VerdictEntry& top = s.ranked[0];
  const VerdictEntry& mid = s.ranked[1];
  const VerdictEntry& last = s.ranked[2];
  EXPECT_FALSE(differs_beyond_two_standard_errors(top, mid));  // Sobol's spread swamps 0.02
  EXPECT_TRUE(differs_beyond_two_standard_errors(mid, last));  // 0.11 against se 0.016
  const std::string md = verdict_markdown(c, runs);
  EXPECT_NE(md.find("It loses to sobol"), std::string::npos) << md;
  EXPECT_NE(md.find("the difference is within two standard errors"), std::string::npos) << md;
  EXPECT_NE(md.find("the difference exceeds two standard errors"), std::string::npos) << md;
  EXPECT_NE(md.find("3 realizations (seeds 1..3)"), std::string::npos) << md;
}

TEST(Verdict, NeedsStatistics) {
  SampleConfig c;
  MethodResult r;
  r.plan.method = Method::cnj;
  EXPECT_TRUE(verdict_statistics({{1, {r}}}).empty());
  EXPECT_THROW(verdict_markdown(c, {{1, {r}}}), std::invalid_argument);
}

}  // namespace
}  // namespace dfvn
