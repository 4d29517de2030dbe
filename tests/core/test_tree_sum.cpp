#include "dfvn/core/tree_sum.hpp"

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
// 1e16 + 1 rounds to 1e16, so each order gives its own answer: left to right, the first would be 0
// and the second 1.
TEST(TreeSum, SumsInTheBalancedOrder) {
  const double three[3] = {1.0, 1e16, -1e16};
  EXPECT_EQ(tree_sum<3>(three), 1.0);  // 1 + (1e16 - 1e16)
  const double four[4] = {1.0, 1e16, -1e16, 1.0};
  EXPECT_EQ(tree_sum<4>(four), 0.0);  // (1 + 1e16) + (-1e16 + 1): both 1s are lost
}

}  // namespace
}  // namespace dfvn
