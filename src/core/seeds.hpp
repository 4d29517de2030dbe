// Seeds of repeated runs: realization r of R runs seed s + r. Unsigned arithmetic would wrap past
// 2^64 - 1 to 0 and silently repeat (or reorder) seeds, so the range is checked first.
#pragma once

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

namespace dfvn {

// Throws std::invalid_argument unless seeds first .. first + count - 1 are all at most 2^64 - 1,
// naming the options that set them (e.g. "--seed" and "--realizations"). count >= 1.
inline void check_seed_range(std::uint64_t first, std::uint64_t count, std::string_view seed_option,
                             std::string_view count_option) {
  constexpr std::uint64_t kLargest = std::numeric_limits<std::uint64_t>::max();
  if (count > 0 && first > kLargest - (count - 1))
    throw std::invalid_argument(fmt::format(
        "{} {} with {} {} needs seeds up to {} + {}, past 2^64 - 1 = {}; give {} at most {}", seed_option, first,
        count_option, count, first, count - 1, kLargest, seed_option, kLargest - (count - 1)));
}

}  // namespace dfvn
