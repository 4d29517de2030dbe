// libFuzzer target: UTK's dat reader (whitespace-separated points, '#' lines between sets), and the
// promise of issue 23 that every text reader reads numbers alike: on input made only of digits,
// signs, exponents, points, spaces, tabs and newlines (one set, no header possible), the dat reader
// and the whitespace reader of `field` must accept the same files with the same numbers.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_contract.hpp"

namespace {

bool plain_numbers(std::string_view bytes) {
  for (char c : bytes)
    if (std::string_view("0123456789eE.+- \t\n").find(c) == std::string_view::npos) return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  dfvn::fuzz::check_reader(bytes, dfvn::InputFormat::dat);
  if (!plain_numbers(bytes)) return 0;
  std::vector<dfvn::PointTable> dat;
  try {
    dat = dfvn::parse_point_sets(bytes, dfvn::InputFormat::dat);
  } catch (const dfvn::InputError&) {
    return 0;
  }
  std::istringstream in{std::string(bytes)};
  dfvn::PointTable text;
  try {
    text = dfvn::read_points_text(in, 0);
  } catch (const dfvn::InputError&) {
    __builtin_trap();  // the dat reader took a file the whitespace reader refuses
  }
  dfvn::fuzz::require(dat.size() == 1 && text.dimension == dat.front().dimension &&
                      text.coordinates == dat.front().coordinates);
  return 0;
}
