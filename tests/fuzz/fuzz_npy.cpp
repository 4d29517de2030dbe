// libFuzzer target: the NPY reader (header scanner, shape arithmetic, C and Fortran order).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_contract.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  dfvn::fuzz::check_reader(std::string_view(reinterpret_cast<const char*>(data), size), dfvn::InputFormat::npy);
  return 0;
}
