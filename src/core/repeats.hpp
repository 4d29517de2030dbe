// Lists given as options (dimensions, methods, study grids) name each value once: a repeat would run
// or count the same thing twice. first_repeat finds one for the caller to refuse by name.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace dfvn {

// The first entry that an earlier entry already holds; nullopt when every entry is distinct.
template <typename T>
std::optional<T> first_repeat(const std::vector<T>& values) {
  for (std::size_t i = 0; i < values.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (values[i] == values[j]) return values[i];
  return std::nullopt;
}

}  // namespace dfvn
