#include "dfvn/io/point_reader.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <sstream>
#include <string>

#include "dfvn/io/csv.hpp"
#include "dfvn/io/point_file.hpp"

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
  EXPECT_EQ(error_of(npy_bytes("<f8", "(1, 2, 2, 2)", values, sizeof values), InputFormat::npy),
            "npy: shape (1, 2, 2, ... 4 extents) is not (points, dimension), (points,) or (sets, points, dimension)");
  EXPECT_EQ(error_of(npy_bytes("<f8", "(0, 2, 2)", values, 0), InputFormat::npy), "npy: shape (0, 2, 2) holds no points");
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
  EXPECT_EQ(error_of("0.1 nan\n", InputFormat::dat),
            "line 1, column 2: 'nan' is not a finite number (NaN and Inf are not allowed)");
}

// Issue 23: the dat reader took "+-0" and "++0.5", which the CSV reader refuses. Every text reader now
// reads numbers with parse_coordinate (io/csv.hpp): each field is accepted or refused alike by all three.
TEST(PointReader, EveryTextReaderReadsNumbersAlike) {
  for (const std::string field : {"+-0", "++0.5", "--1", "-+1", "+", "-", "0x10", "1e", ".", "0.5x", "+.5", "-0",
                                  "+0.5", "5e-324", "1e-400", "1e400", "inf", "-nan", "1_0", "1e+5"}) {
    const std::string csv = "0.25," + field + "\n0.5,0.5\n";  // field in line 1, column 2
    const std::string whitespace = "0.25 " + field + "\n0.5 0.5\n";
    const std::string csv_error = error_of(csv, InputFormat::csv);
    EXPECT_EQ(error_of(whitespace, InputFormat::dat), csv_error) << field;
    std::istringstream text(whitespace);
    std::string text_error = "no error";
    try {
      read_points_text(text, 2);
    } catch (const InputError& e) {
      text_error = e.what();
    }
    EXPECT_EQ(text_error, csv_error) << field;
    double value = 0.0;
    EXPECT_EQ(csv_error == "no error", parse_coordinate(field, value) == NumberText::ok) << field;
  }
  EXPECT_EQ(error_of("0.1 +-0\n", InputFormat::dat), "line 1, column 2: '+-0' is not a number");
  EXPECT_EQ(error_of("++0.5 0.1\n", InputFormat::dat), "line 1, column 1: '++0.5' is not a number");
}

// Issue 23: a header declaring shape (2^62, 8) of '<f8' with no data: rows x N x 8 wrapped past 2^64
// to 0 and passed the size check, then the reader wrote past its buffer.
TEST(PointReader, NpyShapeWhoseByteCountWrapsIsRefused) {
  EXPECT_EQ(error_of(npy_bytes("<f8", "(4611686018427387904, 8)", nullptr, 0), InputFormat::npy),
            "npy: shape (4611686018427387904, 8) of dtype '<f8' needs 2.951e+20 data bytes, the file has 0");
  EXPECT_EQ(error_of(npy_bytes("<f4", "(18446744073709551615, 1)", nullptr, 0), InputFormat::npy),
            "npy: shape (18446744073709551615, 1) of dtype '<f4' needs 7.379e+19 data bytes, the file has 0");
  const double values[2] = {0.5, 0.5};
  EXPECT_EQ(error_of(npy_bytes("<f8", "(2305843009213693953, 8)", values, sizeof values), InputFormat::npy),
            "npy: shape (2305843009213693953, 8) of dtype '<f8' needs 1.476e+20 data bytes, the file has 16");
}

TEST(PointReader, NpyHeaderIsReadStrictly) {
  const double values[4] = {0.1, 0.2, 0.3, 0.4};
  for (const std::string shape : {"(-1, 2)", "(2.0, 2)", "(18446744073709551616, 2)", "(2 2)", "(2, 2", "2, 2", "(0x2, 2)"})
    EXPECT_NE(error_of(npy_bytes("<f8", shape, values, sizeof values), InputFormat::npy), "no error") << shape;
  EXPECT_EQ(error_of(npy_bytes("<f8", "(18446744073709551616, 2)", values, sizeof values), InputFormat::npy),
            "npy: shape extent '18446744073709551616' is above 2^64 - 1");
  EXPECT_EQ(error_of(npy_bytes("<f8", "()", values, sizeof values), InputFormat::npy),
            "npy: shape () is not (points, dimension), (points,) or (sets, points, dimension)");
  EXPECT_EQ(parse_point_sets(npy_bytes("<f8", "( 2 , 2 , )", values, sizeof values), InputFormat::npy)[0].rows(), 2u);
  // Keys: the three numpy writes, no other, none missing.
  std::string no_shape("\x93NUMPY\x01\x00", 8);
  const std::string header = "{'descr': '<f8', 'fortran_order': False}\n";
  no_shape += static_cast<char>(header.size());
  no_shape += '\0';
  no_shape += header;
  EXPECT_EQ(error_of(no_shape, InputFormat::npy), "npy: header has no 'shape'");
  // A long header: the regular expressions that read it recursed once per byte and overflowed the stack.
  std::string long_string(60000, 'x');
  std::string huge("\x93NUMPY\x02\x00", 8);
  const std::string dict = "{'descr': '" + long_string + "', 'fortran_order': False, 'shape': (2, 2), }\n";
  for (int b = 0; b < 4; ++b) huge += static_cast<char>((dict.size() >> (8 * b)) & 0xFF);
  huge += dict;
  const std::string message = error_of(huge, InputFormat::npy);
  EXPECT_EQ(message.substr(0, 20), "npy: dtype 'xxxxxxxx");
  EXPECT_LT(message.size(), 200u) << "the dtype is quoted shortened";
}

TEST(PointReader, NpyOfSeveralSetsInBothOrders) {
  // (2 sets, 3 points, 2 coordinates): set s, point p, coordinate k = s + p / 10 + k / 100.
  double c_order[12], fortran[12];
  for (int set = 0; set < 2; ++set)
    for (int p = 0; p < 3; ++p)
      for (int k = 0; k < 2; ++k) {
        const double v = set + p / 10.0 + k / 100.0;
        c_order[(set * 3 + p) * 2 + k] = v;
        fortran[k * 6 + p * 2 + set] = v;
      }
  for (const bool is_fortran : {false, true}) {
    const auto sets = parse_point_sets(npy_bytes("<f8", "(2, 3, 2)", is_fortran ? fortran : c_order, sizeof c_order, is_fortran),
                                       InputFormat::npy);
    ASSERT_EQ(sets.size(), 2u);
    for (int set = 0; set < 2; ++set) {
      ASSERT_EQ(sets[set].rows(), 3u);
      EXPECT_EQ(sets[set].dimension, 2);
      for (int p = 0; p < 3; ++p)
        for (int k = 0; k < 2; ++k) EXPECT_EQ(sets[set].row(p)[k], set + p / 10.0 + k / 100.0) << is_fortran;
    }
  }
  EXPECT_EQ(error_of(npy_bytes("<f8", "(2, 3, 2)", c_order, 11 * 8), InputFormat::npy),
            "npy: shape (2, 3, 2) of dtype '<f8' needs 96 data bytes, the file has 88");
}

TEST(PointReader, FormatFromExtension) {
  EXPECT_EQ(input_format_from_path("a/b.npy"), InputFormat::npy);
  EXPECT_EQ(input_format_from_path("b.txt"), InputFormat::dat);
  EXPECT_EQ(input_format_from_path("b.bin"), InputFormat::bin);
  EXPECT_THROW(input_format_from_path("b.xyz"), std::invalid_argument);
  EXPECT_THROW(input_format_from_path("-"), std::invalid_argument);
  EXPECT_EQ(parse_input_format("bin"), InputFormat::bin);
}

}  // namespace
}  // namespace dfvn
