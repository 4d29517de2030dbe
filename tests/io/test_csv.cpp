#include "io/csv.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace dfvn {
namespace {

std::string error_of(const std::string& text, int dimension) {
  std::istringstream in(text);
  try {
    read_points_csv(in, dimension);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Csv, ReadsPointsWithOptionalHeader) {
  std::istringstream in("x0,x1\n0.5, 1e-3\n\n-2,3\n");
  const PointTable t = read_points_csv(in, 2);
  ASSERT_EQ(t.rows(), 2u);
  EXPECT_EQ(t.row(0)[1], 1e-3);
  EXPECT_EQ(t.row(1)[0], -2.0);
}

TEST(Csv, ErrorsNameTheLineAndTheProblem) {
  EXPECT_EQ(error_of("1,2\n3\n", 2), "line 2: expected 2 comma-separated columns (--dim 2), found 1");
  EXPECT_EQ(error_of("1,2\n3,abc\n", 2), "line 2, column 2: 'abc' is not a number");
  EXPECT_EQ(error_of("1,nan\n", 2), "line 1, column 2: 'nan' is not a finite number (NaN and Inf are not allowed)");
  EXPECT_EQ(error_of("1,2\n-inf,2\n", 2), "line 2, column 1: '-inf' is not a finite number (NaN and Inf are not allowed)");
  EXPECT_EQ(error_of("1,1e999\n", 2), "line 1, column 2: '1e999' is out of the range of a double");
  EXPECT_EQ(error_of("1,2\nx,y\n", 2), "line 2, column 1: 'x' is not a number");  // only line 1 may be a header
}

TEST(Csv, DoublesRoundTrip) {
  for (double v : {0.1, 1.0 / 3.0, -1e-300, 6.02214076e23, 0.0}) {
    std::string s;
    append_double(s, v);
    EXPECT_EQ(std::stod(s), v) << s;
  }
  EXPECT_EQ(numbered_header("x", 3), "x0,x1,x2");
  EXPECT_EQ(numbered_header("f", 2, 1), "f1,f2");
}

}  // namespace
}  // namespace dfvn
