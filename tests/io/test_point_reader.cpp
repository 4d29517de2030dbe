#include "io/point_reader.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <sstream>
#include <string>

#include "io/point_file.hpp"

namespace dfvn {
namespace {

std::string npy_bytes(const std::string& descr, const std::string& shape, const void* data, std::size_t bytes,
                      bool fortran = false) {
  std::string header = "{'descr': '" + descr + "', 'fortran_order': " + (fortran ? "True" : "False") +
                       ", 'shape': " + shape + ", }";
  header.append((64 - (10 + header.size() + 1) % 64) % 64, ' ');
  header += '\n';
  std::string out("\x93NUMPY\x01\x00", 8);
  out += static_cast<char>(header.size() & 0xFF);
  out += static_cast<char>(header.size() >> 8);
  out += header;
  out.append(static_cast<const char*>(data), bytes);
  return out;
}

std::string error_of(std::string_view bytes, InputFormat format) {
  try {
    parse_point_sets(bytes, format);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(PointReader, CsvWithAndWithoutHeaderFixesTheDimension) {
  for (const std::string text : {"x0,x1,x2\n0.1,0.2,0.3\n0.4,0.5,0.6\n", "0.1,0.2,0.3\n\n0.4,0.5,0.6\n"}) {
    const auto sets = parse_point_sets(text, InputFormat::csv);
    ASSERT_EQ(sets.size(), 1u);
    EXPECT_EQ(sets[0].dimension, 3);
    ASSERT_EQ(sets[0].rows(), 2u);
    EXPECT_EQ(sets[0].row(1)[2], 0.6);
  }
  const auto one = parse_point_sets("0.5\n0.25\n", InputFormat::csv);
  EXPECT_EQ(one[0].dimension, 1);
}

TEST(PointReader, CsvErrorsNameTheLine) {
  EXPECT_EQ(error_of("0.1,0.2\n0.3\n", InputFormat::csv), "line 2: expected 2 comma-separated columns (as in the first line), found 1");
  EXPECT_EQ(error_of("0.1,0.2\n0.3,abc\n", InputFormat::csv), "line 2, column 2: 'abc' is not a number");
  EXPECT_EQ(error_of("1,2,3,4,5,6,7,8,9\n", InputFormat::csv), "line 1: 9 coordinates per point; allowed 1..8");
  EXPECT_EQ(error_of("x0,x1\n", InputFormat::csv), "the file holds no points, only a header");
  EXPECT_EQ(error_of("", InputFormat::csv), "the file holds no points");
}

TEST(PointReader, NpyFloat64AndFloat32InBothOrders) {
  const double c_order[6] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6};  // (3, 2)
  auto sets = parse_point_sets(npy_bytes("<f8", "(3, 2)", c_order, sizeof c_order), InputFormat::npy);
  ASSERT_EQ(sets.size(), 1u);
  EXPECT_EQ(sets[0].dimension, 2);
  EXPECT_EQ(sets[0].row(2)[0], 0.5);
  const float single[6] = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f};
  sets = parse_point_sets(npy_bytes("<f4", "(3, 2)", single, sizeof single), InputFormat::npy);
  EXPECT_EQ(sets[0].row(1)[1], static_cast<double>(0.4f));
  sets = parse_point_sets(npy_bytes("<f8", "(3, 2)", c_order, sizeof c_order, true), InputFormat::npy);
  EXPECT_EQ(sets[0].row(0)[1], 0.4);  // Fortran order: column 1 starts at element 3
  sets = parse_point_sets(npy_bytes("<f8", "(6,)", c_order, sizeof c_order), InputFormat::npy);
  EXPECT_EQ(sets[0].dimension, 1);
  EXPECT_EQ(sets[0].rows(), 6u);
}

TEST(PointReader, NpyWrittenByUsReadsBack) {
  const PointSet points{3, {0.1, 0.2, 0.3, 0.7, 0.8, 0.9}, Box{}};
  std::ostringstream out;
  write_npy(out, points);
  const auto sets = parse_point_sets(out.str(), InputFormat::npy);
  EXPECT_EQ(sets[0].coordinates, points.coordinates);
}

TEST(PointReader, NpyErrorsNameDtypeAndShape) {
  const std::int64_t integers[4] = {1, 2, 3, 4};
  EXPECT_EQ(error_of(npy_bytes("<i8", "(2, 2)", integers, sizeof integers), InputFormat::npy),
            "npy: dtype '<i8' is not supported (allowed float64 '<f8' and float32 '<f4')");
  const double values[8] = {};
  EXPECT_EQ(error_of(npy_bytes("<f8", "(2, 2, 2)", values, sizeof values), InputFormat::npy),
            "npy: shape (2, 2, 2) is not (points, dimension) or (points,)");
  EXPECT_EQ(error_of(npy_bytes("<f8", "(1, 9)", values, sizeof values), InputFormat::npy),
            "npy: shape (1, 9): 9 coordinates per point; allowed 1..8");
  EXPECT_EQ(error_of(npy_bytes("<f8", "(3, 2)", values, 5 * 8), InputFormat::npy),
            "npy: shape (3, 2) of dtype '<f8' needs 48 data bytes, the file has 40");
  EXPECT_EQ(error_of("hello", InputFormat::npy), "not a NumPy .npy file (no \\x93NUMPY magic)");
}

TEST(PointReader, DatSetsSeparatedByHashLines) {
  const auto sets = parse_point_sets("# set 0\n0.1 0.2\n0.3\t0.4\n#\n# set 1\n0.5 0.6\n", InputFormat::dat);
  ASSERT_EQ(sets.size(), 2u);
  EXPECT_EQ(sets[0].rows(), 2u);
  EXPECT_EQ(sets[1].rows(), 1u);
  EXPECT_EQ(sets[1].row(0)[1], 0.6);
  EXPECT_EQ(error_of("0.1 0.2\n#\n0.1 0.2 0.3\n", InputFormat::dat),
            "line 3: expected 2 whitespace-separated numbers (as in the first point), found 3");
  EXPECT_EQ(error_of("0.1 x\n", InputFormat::dat), "line 1, column 2: 'x' is not a number");
  EXPECT_EQ(error_of("0.1 nan\n", InputFormat::dat), "line 1, column 2: 'nan' is not a finite number");
}

TEST(PointReader, FormatFromExtension) {
  EXPECT_EQ(input_format_from_path("a/b.npy"), InputFormat::npy);
  EXPECT_EQ(input_format_from_path("b.txt"), InputFormat::dat);
  EXPECT_THROW(input_format_from_path("b.bin"), std::invalid_argument);
}

}  // namespace
}  // namespace dfvn
