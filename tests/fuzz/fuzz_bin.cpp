// libFuzzer target: UTK's binary .bin reader (record walk, dimension search, counts near 2^32).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_contract.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  dfvn::fuzz::check_reader(std::string_view(reinterpret_cast<const char*>(data), size), dfvn::InputFormat::bin);
  return 0;
}
