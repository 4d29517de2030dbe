// first_repeat: the first entry an earlier one already holds.
#include "dfvn/core/repeats.hpp"

#include <gtest/gtest.h>

#include <string>

namespace dfvn {
namespace {

TEST(FirstRepeat, FindsTheFirstEntryThatRepeatsAnEarlierOne) {
  EXPECT_EQ(first_repeat(std::vector<int>{}), std::nullopt);
  EXPECT_EQ(first_repeat(std::vector<int>{3}), std::nullopt);
  EXPECT_EQ(first_repeat(std::vector<int>{3, 4, 5}), std::nullopt);
  EXPECT_EQ(first_repeat(std::vector<int>{3, 4, 3}), 3);
  EXPECT_EQ(first_repeat(std::vector<int>{5, 4, 4, 5}), 4);  // the second 4 comes before the second 5
  EXPECT_EQ(first_repeat(std::vector<double>{0.2, 0.35, 0.2}), 0.2);
  EXPECT_EQ(first_repeat(std::vector<std::string>{"cnj", "sobol"}), std::nullopt);
}

}  // namespace
}  // namespace dfvn
