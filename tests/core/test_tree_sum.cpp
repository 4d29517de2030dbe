#include "core/tree_sum.hpp"

#include <gtest/gtest.h>

namespace dfvn {
namespace {

TEST(TreeSum, AddsEveryEntry) {
  const double p[9] = {1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0, 128.0, 256.0};
  EXPECT_EQ(tree_sum<1>(p), 1.0);
  EXPECT_EQ(tree_sum<2>(p), 3.0);
  EXPECT_EQ(tree_sum<3>(p), 7.0);
  EXPECT_EQ(tree_sum<7>(p), 127.0);
  EXPECT_EQ(tree_sum<8>(p), 255.0);
  EXPECT_EQ(tree_sum<9>(p), 511.0);
}

// The order is the balanced tree: p0 + (p1 + p2) for three numbers, (p0 + p1) + (p2 + p3) for four.
// Left to right, both would lose the 1 against 1e16.
TEST(TreeSum, SumsInTheBalancedOrder) {
  const double three[3] = {1.0, 1e16, -1e16};
  EXPECT_EQ(tree_sum<3>(three), 1.0);
  EXPECT_EQ((three[0] + three[1]) + three[2], 0.0);
  const double four[4] = {1e16, -1e16, 1.0, 1.0};
  EXPECT_EQ(tree_sum<4>(four), 2.0);
  const double four_split[4] = {1e16, 1.0, -1e16, 1.0};
  EXPECT_EQ(tree_sum<4>(four_split), 0.0);  // (1e16 + 1) + (-1e16 + 1): both 1s are lost
}

}  // namespace
}  // namespace dfvn
