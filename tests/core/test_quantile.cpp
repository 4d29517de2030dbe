#include "dfvn/core/quantile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace dfvn {
namespace {

// Values from numpy 1.24: numpy.quantile([1, 2, 4, 8, 16], q) for q = 0, 0.01, 0.1, 0.5, 0.9, 1 and
// numpy.median of five and of four values.
TEST(Quantile, MatchesNumpysLinearMethod) {
  const std::vector<double> v{1.0, 2.0, 4.0, 8.0, 16.0};
  EXPECT_EQ(quantile_of_sorted(v, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(quantile_of_sorted(v, 0.01), 1.04);
  EXPECT_DOUBLE_EQ(quantile_of_sorted(v, 0.1), 1.4);
  EXPECT_EQ(quantile_of_sorted(v, 0.5), 4.0);
  EXPECT_DOUBLE_EQ(quantile_of_sorted(v, 0.9), 12.8);
  EXPECT_EQ(quantile_of_sorted(v, 1.0), 16.0);
  EXPECT_EQ(median_of_sorted(v), 4.0);
  EXPECT_EQ(median_of_sorted({1.0, 2.0, 4.0, 8.0}), 3.0);
}

TEST(Quantile, OneValueAndNoValues) {
  EXPECT_EQ(quantile_of_sorted({5.0}, 0.3), 5.0);
  EXPECT_EQ(median_of_sorted({5.0}), 5.0);
  EXPECT_THROW(quantile_of_sorted({}, 0.5), std::invalid_argument);
  EXPECT_THROW(median_of_sorted({}), std::invalid_argument);
  EXPECT_THROW(quantile_of_sorted({1.0, 2.0}, 1.5), std::invalid_argument);
  EXPECT_THROW(quantile_of_sorted({1.0, 2.0}, -0.1), std::invalid_argument);
  EXPECT_THROW(quantile_of_sorted({1.0, 2.0}, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace dfvn
