// libFuzzer target: the CSV reader of `stats`, and read_points_text, the reader of `field` (CSV or
// whitespace-separated, dimension from the first line or given).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>

#include "fuzz_contract.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  dfvn::fuzz::check_reader(bytes, dfvn::InputFormat::csv);
  for (int dimension : {0, 3}) {
    std::istringstream in{std::string(bytes)};
    try {
      const dfvn::PointTable table = dfvn::read_points_text(in, dimension);
      // No points is allowed here (the field command writes only a header then).
      if (table.rows() > 0) dfvn::fuzz::check_table(table, table.dimension);
      dfvn::fuzz::require(table.dimension >= 1 && table.dimension <= 16 && (dimension == 0 || table.dimension == dimension));
    } catch (const dfvn::InputError& error) {
      dfvn::fuzz::check_error(error);
    }
  }
  return 0;
}
