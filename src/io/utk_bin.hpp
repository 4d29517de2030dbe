// UTK's binary point-set format (.bin), read and written byte for byte as UTK writes it.
//
// The layout, from UTK's source (github.com/utk-team/utk, src/io/fileIO_bin.hpp, classes
// PointsetWriter_BIN / PointsetReader_BIN; UTK 2's include/utk/utils/PointsetIO.hpp has only the
// text format): a file is a sequence of sets, one record per set, to the end of the file:
//   unsigned int s                        4 bytes, the number of points of the set
//   s points                              s x sizeof(Point<D, T>) bytes
// where Point<D, T> (src/pointsets/Point.hpp) holds one Vector<D, T> (src/pointsets/Vector.hpp)
// whose only member is `T data[D]`: the D coordinates of a point, point after point. UTK's samplers
// write T = double. Every number is in the writing machine's byte order (little endian on x86 and
// arm64, the only order read and written here). There is no magic, no header, and neither the
// dimension D nor the type T is stored: UTK's reader is compiled for one D. So here T is float64 and
// D is given, or else found as the only dimension 1..8 with which the records fill the file exactly.
#pragma once

#include <ostream>
#include <string_view>
#include <vector>

#include "dfvn/core/point_set.hpp"
#include "dfvn/io/csv.hpp"

namespace dfvn {

// One record: the set's point count (throws std::invalid_argument above 2^32 - 1) and its points.
void write_utk_bin(std::ostream& out, const PointSet& points);

// The dimensions 1..8 with which `bytes` is a whole sequence of records (at least one).
std::vector<int> utk_bin_dimensions(std::string_view bytes);

// The sets of a .bin file of `dimension` (0: the only one utk_bin_dimensions finds). Throws
// InputError with one line: no dimension or several fit, a record runs past the end of the file (at
// which set and byte), a set holds no points, or a coordinate is not finite.
std::vector<PointTable> parse_utk_bin(std::string_view bytes, int dimension = 0);

}  // namespace dfvn
