// UTK's binary .bin (io/utk_bin.hpp) and the files of several sets (io/point_file.hpp).
#include "dfvn/io/utk_bin.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "dfvn/io/point_file.hpp"
#include "dfvn/io/point_reader.hpp"

namespace dfvn {
namespace {

PointSet make_set(int dimension, std::size_t points, double offset) {
  PointSet set{dimension, Coordinates(points * dimension), Box{}};
  for (std::size_t k = 0; k < set.coordinates.size(); ++k) set.coordinates[k] = offset + 1.0 / (3.0 + k);
  return set;
}

std::string error_of(std::string_view bytes, int dimension = 0) {
  try {
    parse_utk_bin(bytes, dimension);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// A record as UTK's PointsetWriter_BIN writes it, built by hand from the documented layout: the
// unsigned int count in 4 little-endian bytes, then each double's 8 little-endian bytes.
std::string record(std::uint32_t count, const std::vector<double>& values) {
  std::string out;
  for (int b = 0; b < 4; ++b) out += static_cast<char>((count >> (8 * b)) & 0xFF);
  for (double v : values) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, 8);
    for (int b = 0; b < 8; ++b) out += static_cast<char>((bits >> (8 * b)) & 0xFF);
  }
  return out;
}

TEST(UtkBin, ReadsAHandBuiltFile) {
  // Two 2D sets: 2 points, then 1 point.
  const std::string bytes = record(2, {0.25, 0.5, 0.75, 1.0}) + record(1, {0.125, 0.375});
  ASSERT_EQ(bytes.size(), 4u + 32u + 4u + 16u);
  EXPECT_EQ(bytes.substr(0, 4), std::string("\x02\x00\x00\x00", 4));
  const auto sets = parse_point_sets(bytes, InputFormat::bin);
  ASSERT_EQ(sets.size(), 2u);
  EXPECT_EQ(sets[0].dimension, 2);
  ASSERT_EQ(sets[0].rows(), 2u);
  EXPECT_EQ(sets[0].row(1)[0], 0.75);
  EXPECT_EQ(sets[0].row(1)[1], 1.0);
  ASSERT_EQ(sets[1].rows(), 1u);
  EXPECT_EQ(sets[1].row(0)[1], 0.375);
  // Written again, the same bytes.
  std::vector<PointSet> again;
  for (const auto& t : sets) again.push_back(PointSet{t.dimension, t.coordinates, Box{}});
  std::ostringstream out;
  write_point_sets(out, again, PointFormat::bin);
  EXPECT_EQ(out.str(), bytes);
}

TEST(UtkBin, RoundTripIsBitForBit) {
  for (int dimension : {1, 2, 3, 7, 8}) {
    const std::vector<PointSet> sets = {make_set(dimension, 100, 0.0), make_set(dimension, 37, 1e-300),
                                        make_set(dimension, 5, 0.1)};
    std::ostringstream first;
    write_point_sets(first, sets, PointFormat::bin);
    EXPECT_EQ(first.str().size(), 3 * 4 + (100 + 37 + 5) * 8 * static_cast<std::size_t>(dimension));
    const auto read = parse_point_sets(first.str(), InputFormat::bin, dimension);
    ASSERT_EQ(read.size(), 3u);
    std::vector<PointSet> again;
    for (const auto& t : read) again.push_back(PointSet{t.dimension, t.coordinates, Box{}});
    std::ostringstream second;
    write_point_sets(second, again, PointFormat::bin);
    EXPECT_EQ(first.str(), second.str()) << dimension << "D";
  }
}

TEST(UtkBin, FindsTheOneDimensionThatFits) {
  // 4 + 10 x 3 x 8 bytes: only 3D reads whole (no other D makes the first record end at the end).
  const std::vector<PointSet> sets = {make_set(3, 10, 0.0)};
  std::ostringstream out;
  write_point_sets(out, sets, PointFormat::bin);
  EXPECT_EQ(utk_bin_dimensions(out.str()), std::vector<int>{3});
  EXPECT_EQ(parse_point_sets(out.str(), InputFormat::bin)[0].dimension, 3);
  // A record of 0 points followed by nothing fits every dimension: ambiguous, and then empty.
  const std::string empty = record(0, {});
  EXPECT_EQ(utk_bin_dimensions(empty).size(), 8u);
  EXPECT_EQ(error_of(empty), "bin: the file reads whole as 1D and as 2D points (.bin does not store the dimension); give --dim");
}

TEST(UtkBin, MalformedFilesAreRefusedWithOneLine) {
  EXPECT_EQ(error_of(""), "bin: the file holds no points (0 bytes)");
  EXPECT_EQ(error_of("abc"),
            "bin: 3 bytes are not UTK .bin records (a 4-byte point count, then the float64 points) of any dimension 1..8: "
            "truncated, or not a UTK .bin file");
  // Truncated: the second record lacks its last byte.
  std::string truncated = record(2, {0.25, 0.5, 0.75, 1.0}) + record(1, {0.125, 0.375});
  truncated.pop_back();
  EXPECT_EQ(error_of(truncated, 2),
            "bin: as 2D points, set 1's record at byte 36 runs past the end of the file (55 bytes): truncated, or not 2D");
  // An empty set among others.
  EXPECT_EQ(error_of(record(1, {0.5, 0.5}) + record(0, {}), 2), "bin: set 1 (at byte 20) holds no points");
  // A count far beyond the file.
  EXPECT_EQ(error_of(record(0xFFFFFFFFu, {0.5, 0.5}), 2),
            "bin: as 2D points, set 0's record at byte 0 runs past the end of the file (20 bytes): truncated, or not 2D");
  EXPECT_EQ(error_of(record(1, {0.5, 1.0 / 0.0}), 2), "bin: set 0, point 0, coordinate 1 is inf (only finite numbers are allowed)");
  EXPECT_EQ(error_of(record(1, {0.5}), 9), "bin: dimension 9; allowed 1..8");
}

TEST(PointSets, DatSeparatesSetsAsUtkDoesAndReadsBack) {
  const std::vector<PointSet> sets = {make_set(2, 3, 0.0), make_set(2, 2, 0.5)};
  std::ostringstream out;
  write_point_sets(out, sets, PointFormat::dat);
  const std::string text = out.str();
  // UTK's write_text_pointsets: a line "#" between sets, none before the first or after the last.
  EXPECT_EQ(std::count(text.begin(), text.end(), '#'), 1);
  EXPECT_NE(text.find("\n#\n"), std::string::npos);
  EXPECT_NE(text.front(), '#');
  const auto read = parse_point_sets(text, InputFormat::dat);
  ASSERT_EQ(read.size(), 2u);
  for (std::size_t s = 0; s < 2; ++s) {
    ASSERT_EQ(read[s].rows(), sets[s].size());
    for (std::size_t k = 0; k < sets[s].coordinates.size(); ++k) EXPECT_EQ(read[s].coordinates[k], sets[s].coordinates[k]);
  }
  // One set: as write_point_file writes it, no '#'.
  std::ostringstream one, file;
  write_point_sets(one, {sets[0]}, PointFormat::dat);
  write_points_dat(file, sets[0]);
  EXPECT_EQ(one.str(), file.str());
}

TEST(PointSets, NpyHoldsSetsOfOneSizeAsOneArray) {
  const std::vector<PointSet> sets = {make_set(3, 4, 0.0), make_set(3, 4, 0.25)};
  std::ostringstream out;
  write_point_sets(out, sets, PointFormat::npy);
  EXPECT_NE(out.str().find("'shape': (2, 4, 3)"), std::string::npos);
  const auto read = parse_point_sets(out.str(), InputFormat::npy);
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[1].row(3)[2], sets[1].point(3)[2]);
  EXPECT_EQ(std::memcmp(read[0].coordinates.data(), sets[0].coordinates.data(), 12 * sizeof(double)), 0);
  // One set: (points, N) as before.
  std::ostringstream one;
  write_point_sets(one, {sets[0]}, PointFormat::npy);
  EXPECT_NE(one.str().find("'shape': (4, 3)"), std::string::npos);
}

TEST(PointSets, FormatsThatCannotHoldTheSetsAreRefused) {
  const std::vector<PointSet> unequal = {make_set(2, 4, 0.0), make_set(2, 5, 0.0)};
  try {
    check_point_sets_fit(unequal, PointFormat::npy);
    ADD_FAILURE() << "npy took sets of different sizes";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "npy holds sets of one size as an array (sets, points, N); set 0 has 4 points, set 1 has 5: use dat or bin");
  }
  EXPECT_THROW(check_point_sets_fit(unequal, PointFormat::csv), std::invalid_argument);
  EXPECT_NO_THROW(check_point_sets_fit(unequal, PointFormat::dat));
  EXPECT_NO_THROW(check_point_sets_fit(unequal, PointFormat::bin));
  EXPECT_NO_THROW(check_point_sets_fit({unequal[0]}, PointFormat::csv));
  EXPECT_THROW(check_point_sets_fit({make_set(2, 4, 0.0), make_set(3, 4, 0.0)}, PointFormat::bin), std::invalid_argument);
  EXPECT_THROW(check_point_sets_fit({}, PointFormat::dat), std::invalid_argument);
}

}  // namespace
}  // namespace dfvn
