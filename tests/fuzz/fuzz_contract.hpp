// What every reader promises, checked on each fuzz input: either InputError (a bad file, one line of
// text) or point sets of one dimension in 1..8, each non-empty, every coordinate finite. Any other
// exception escapes to libFuzzer, which reports it as a crash; a broken promise traps.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "dfvn/io/csv.hpp"
#include "dfvn/io/point_reader.hpp"

namespace dfvn::fuzz {

inline void require(bool promise) {
  if (!promise) __builtin_trap();
}

inline void check_error(const InputError& error) {
  const std::string message = error.what();
  require(!message.empty() && message.size() < 1000);  // messages quote input shortened
}

inline void check_table(const PointTable& table, int dimension) {
  require(table.dimension == dimension);
  require(table.rows() >= 1 && table.coordinates.size() == table.rows() * static_cast<std::size_t>(dimension));
  for (double x : table.coordinates) require(std::isfinite(x));
}

inline void check_sets(const std::vector<PointTable>& sets) {
  require(!sets.empty());
  const int dimension = sets.front().dimension;
  require(dimension >= kMinInputDimension && dimension <= kMaxInputDimension);
  for (const PointTable& table : sets) check_table(table, dimension);
}

// parse_point_sets of `bytes` in `format`: either InputError or sets that keep the promise.
inline void check_reader(std::string_view bytes, InputFormat format) {
  try {
    check_sets(parse_point_sets(bytes, format));
  } catch (const InputError& error) {
    check_error(error);
  }
}

}  // namespace dfvn::fuzz
