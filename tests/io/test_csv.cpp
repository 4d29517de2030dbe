#include "dfvn/io/csv.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

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

TEST(Csv, QuotedNumbersAreNumbersAndAHeaderIsOnlyTheFirstNonNumericLine) {
  std::istringstream quoted_data("\"0.1\",\"0.2\"\n \"3\" , 4\n");
  const PointTable t = read_points_csv(quoted_data, 2);
  ASSERT_EQ(t.rows(), 2u) << "a quoted data line was taken as a header";
  EXPECT_EQ(t.row(0)[0], 0.1);
  EXPECT_EQ(t.row(1)[0], 3.0);
  std::istringstream quoted_header("\"x0\",\"x,1\"\n1,2\n");
  EXPECT_EQ(read_points_csv(quoted_header, 2).rows(), 1u);
  EXPECT_EQ(error_of("x0,1\n2,3\n", 2), "line 1, column 1: 'x0' is not a number");  // half a header
  EXPECT_EQ(error_of("\"1,2\n", 2), "line 1, column 1: unterminated quote");
  EXPECT_EQ(error_of("\"1\"x,2\n", 2), "line 1, column 1: text after the closing quote");
}

TEST(Csv, SignsAndByteOrderMarks) {
  std::istringstream plus("+1,-2\n");
  EXPECT_EQ(read_points_csv(plus, 2).row(0)[0], 1.0);
  EXPECT_EQ(error_of("+-1,2\n", 2), "line 1, column 1: '+-1' is not a number");
  EXPECT_EQ(error_of("1,++2\n", 2), "line 1, column 2: '++2' is not a number");
  EXPECT_EQ(error_of("1,--2\n", 2), "line 1, column 2: '--2' is not a number");
  std::istringstream bom("\xEF\xBB\xBFx0,x1\n1,2\n");
  EXPECT_EQ(read_points_csv(bom, 2).rows(), 1u);
  EXPECT_EQ(error_of("1,2\n\xEF\xBB\xBF" "3,4\n", 2), "line 2, column 1: '\\xEF\\xBB\\xBF3' is not a number");
}

TEST(Csv, OffendingTextIsShortenedAndEscaped) {
  EXPECT_EQ(error_of("1," + std::string(100000, 'a') + "\n", 2),
            "line 1, column 2: '" + std::string(40, 'a') + "...' (100000 bytes) is not a number");
  EXPECT_EQ(error_of(std::string("1,2\0x\n", 7), 2), "line 1, column 2: '2\\0x' is not a number");
  EXPECT_EQ(error_of("1,\x1B[31m\n", 2), "line 1, column 2: '\\x1B[31m' is not a number");
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


PointTable read_text(const std::string& text, int dimension) {
  std::istringstream in(text);
  return read_points_text(in, dimension);
}

std::string text_error_of(const std::string& text, int dimension) {
  try {
    read_text(text, dimension);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// numpy.savetxt's default: spaces between numbers, '#' comments; the first line sets the dimension.
TEST(Csv, ReadsWhitespaceSeparatedPointsAndInfersTheDimension) {
  const PointTable t = read_text("# x0 x1 x2\n1.5e-01 2 3\n\t4  5\t6\n\n", 0);
  EXPECT_EQ(t.dimension, 3);
  EXPECT_EQ(t.coordinates, (Coordinates{0.15, 2, 3, 4, 5, 6}));
  EXPECT_EQ(read_text("x y\n1 2\n", 0).coordinates, (Coordinates{1, 2}));  // a header line
  const PointTable csv = read_text("x0,x1\n0.5,0.25\n", 0);
  EXPECT_EQ(csv.dimension, 2);
  EXPECT_EQ(csv.coordinates, (Coordinates{0.5, 0.25}));
  EXPECT_EQ(read_text("1 2 3\n", 3).dimension, 3);
}

TEST(Csv, WhitespaceErrorsNameTheLineAndTheDimensionsOrigin) {
  EXPECT_EQ(text_error_of("1 2 3\n4 5\n", 0), "line 2: expected 3 whitespace-separated columns (as in the first line), found 2");
  EXPECT_EQ(text_error_of("1 2 3\n4 5\n", 3), "line 2: expected 3 whitespace-separated columns (--dim 3), found 2");
  EXPECT_EQ(text_error_of("1,2,3\n4,5\n", 0), "line 2: expected 3 comma-separated columns (as in the first line), found 2");
  EXPECT_EQ(text_error_of("1 2\n3 zz\n", 0), "line 2, column 2: 'zz' is not a number");
  EXPECT_EQ(text_error_of("1 nan\n", 0), "line 1, column 2: 'nan' is not a finite number (NaN and Inf are not allowed)");
  EXPECT_EQ(text_error_of("# only a comment\n", 0), "no points in the input");
}

TEST(Csv, RealsKeepTheirTypeInEveryRun) {
  EXPECT_EQ(format_real(1.0), "1.0");
  EXPECT_EQ(format_real(0.6), "0.6");
  EXPECT_EQ(format_real(0.1 * 6), "0.6");  // nine significant digits
  EXPECT_EQ(format_real(1e-5), "1e-05");
  EXPECT_EQ(format_real(-3.0), "-3.0");
  EXPECT_EQ(format_real(123456789012.0), "1.23456789e+11");
  EXPECT_EQ(format_real(0.0), "0.0");
  EXPECT_EQ(format_real(2.0, 6), "2.0");
  EXPECT_EQ(format_real(1e6, 6), "1e+06");
  // One spelling each for the values that are not finite.
  EXPECT_EQ(format_real(std::nan("")), "nan");
  EXPECT_EQ(format_real(HUGE_VAL), "inf");
  EXPECT_EQ(format_real(-HUGE_VAL), "-inf");
  // The 17-digit form of point coordinates and field values: a decimal point too, appended in place.
  std::string s = "x,";
  append_double(s, 0.0);
  append_double(s += ',', 1.0);
  append_double(s += ',', 0.5);
  append_double(s += ',', -2e300);
  EXPECT_EQ(s, "x,0.0,1.0,0.5,-2.0000000000000001e+300");
}

}  // namespace
}  // namespace dfvn
