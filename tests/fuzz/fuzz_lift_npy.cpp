// libFuzzer target: the NPY reader of --lift npy:FILE's height grids (parse_npy_matrix: a 2D float64 or
// float32 array, C or Fortran order). Its promise, checked on every input: either InputError (one line of
// text) or a rows x columns matrix, each side in 2..kMaxNpyMatrixSide, every element finite.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_contract.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using dfvn::fuzz::require;
  try {
    const dfvn::NpyMatrix m = dfvn::parse_npy_matrix(std::string_view(reinterpret_cast<const char*>(data), size));
    require(m.rows >= 2 && m.columns >= 2);
    require(static_cast<std::uint64_t>(m.rows) <= dfvn::kMaxNpyMatrixSide &&
            static_cast<std::uint64_t>(m.columns) <= dfvn::kMaxNpyMatrixSide);
    require(m.values.size() == static_cast<std::size_t>(m.rows) * static_cast<std::size_t>(m.columns));
    for (double v : m.values) require(std::isfinite(v));
  } catch (const dfvn::InputError& error) {
    dfvn::fuzz::check_error(error);
  }
  return 0;
}
