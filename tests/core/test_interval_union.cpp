#include "dfvn/core/interval_union.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace dfvn {
namespace {

TEST(IntervalUnion, MergesOverlapsAndHoldsTheEnds) {
  const IntervalUnion u({{5.0, 6.0}, {0.0, 1.0}, {0.5, 2.0}, {2.0, 3.0}, {7.5, 7.5}});
  ASSERT_EQ(u.intervals().size(), 3u);
  EXPECT_EQ(u.intervals()[0], (IntervalUnion::Interval{0.0, 3.0}));  // touching intervals merge
  EXPECT_EQ(u.intervals()[1], (IntervalUnion::Interval{5.0, 6.0}));
  EXPECT_EQ(u.intervals()[2], (IntervalUnion::Interval{7.5, 7.5}));
  for (double z : {0.0, 1.5, 3.0, 5.0, 6.0, 7.5}) EXPECT_TRUE(u.contains(z)) << z;
  for (double z : {-0.1, 3.0000001, 4.0, 6.5, 7.4, 8.0}) EXPECT_FALSE(u.contains(z)) << z;
}

TEST(IntervalUnion, EmptyAndUnbounded) {
  EXPECT_FALSE(IntervalUnion().contains(0.0));
  EXPECT_TRUE(IntervalUnion(std::vector<IntervalUnion::Interval>{}).intervals().empty());
  const double inf = std::numeric_limits<double>::infinity();
  const IntervalUnion u({{-inf, -1.0}, {1.0, inf}});
  EXPECT_TRUE(u.contains(-1e300));
  EXPECT_TRUE(u.contains(1e300));
  EXPECT_FALSE(u.contains(0.0));
}

}  // namespace
}  // namespace dfvn
