#include "dfvn/io/utk_bin.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace dfvn {

static_assert(std::endian::native == std::endian::little, "UTK's .bin is read and written in little-endian order");

namespace {

constexpr int kMaxBinDimension = 8;

std::uint32_t count_at(std::string_view bytes, std::size_t at) {
  std::uint32_t count;
  std::memcpy(&count, bytes.data() + at, 4);
  return count;
}

// Where the walk of records of `dimension` stops: bytes.size() when they fill the file exactly.
struct Walk {
  std::size_t sets = 0;
  std::size_t stopped_at = 0;  // offset of the record that does not fit
  bool whole = false;
};

Walk walk(std::string_view bytes, int dimension) {
  Walk w;
  std::size_t at = 0;
  const std::uint64_t point_bytes = 8u * static_cast<std::uint64_t>(dimension);
  while (at < bytes.size()) {
    w.stopped_at = at;
    if (bytes.size() - at < 4) return w;
    const std::uint64_t need = count_at(bytes, at) * point_bytes;  // < 2^32 x 64: no overflow
    if (need > bytes.size() - at - 4) return w;
    at += 4 + need;
    ++w.sets;
  }
  w.whole = w.sets > 0;
  return w;
}

}  // namespace

void write_utk_bin(std::ostream& out, const PointSet& points) {
  if (points.size() > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument(fmt::format("UTK's .bin holds at most 2^32 - 1 points a set; this set has {}", points.size()));
  const auto count = static_cast<std::uint32_t>(points.size());
  out.write(reinterpret_cast<const char*>(&count), 4);
  out.write(reinterpret_cast<const char*>(points.coordinates.data()),
            static_cast<std::streamsize>(points.coordinates.size() * sizeof(double)));
}

std::vector<int> utk_bin_dimensions(std::string_view bytes) {
  std::vector<int> fits;
  for (int d = 1; d <= kMaxBinDimension; ++d)
    if (walk(bytes, d).whole) fits.push_back(d);
  return fits;
}

std::vector<PointTable> parse_utk_bin(std::string_view bytes, int dimension) {
  if (bytes.empty()) throw InputError("bin: the file holds no points (0 bytes)");
  if (dimension == 0) {
    const std::vector<int> fits = utk_bin_dimensions(bytes);
    if (fits.empty())
      throw InputError(fmt::format("bin: {} bytes are not UTK .bin records (a 4-byte point count, then the float64 points) "
                                   "of any dimension 1..{}: truncated, or not a UTK .bin file",
                                   bytes.size(), kMaxBinDimension));
    if (fits.size() > 1)
      throw InputError(fmt::format("bin: the file reads whole as {}D and as {}D points (.bin does not store the dimension); "
                                   "give --dim", fits[0], fits[1]));
    dimension = fits.front();
  }
  if (dimension < 1 || dimension > kMaxBinDimension)
    throw InputError(fmt::format("bin: dimension {}; allowed 1..{}", dimension, kMaxBinDimension));
  const Walk w = walk(bytes, dimension);
  if (!w.whole)
    throw InputError(fmt::format("bin: as {}D points, set {}'s record at byte {} runs past the end of the file ({} bytes): "
                                 "truncated, or not {}D",
                                 dimension, w.sets, w.stopped_at, bytes.size(), dimension));
  std::vector<PointTable> sets;
  std::size_t at = 0;
  while (at < bytes.size()) {
    const std::uint32_t count = count_at(bytes, at);
    at += 4;
    if (count == 0) throw InputError(fmt::format("bin: set {} (at byte {}) holds no points", sets.size(), at - 4));
    PointTable table{dimension, Coordinates(std::size_t{count} * dimension)};
    std::memcpy(table.coordinates.data(), bytes.data() + at, table.coordinates.size() * 8);
    for (std::size_t k = 0; k < table.coordinates.size(); ++k)
      if (!std::isfinite(table.coordinates[k]))
        throw InputError(fmt::format("bin: set {}, point {}, coordinate {} is {} (only finite numbers are allowed)", sets.size(),
                                     k / dimension, k % dimension, table.coordinates[k]));
    at += table.coordinates.size() * 8;
    sets.push_back(std::move(table));
  }
  return sets;
}

}  // namespace dfvn
