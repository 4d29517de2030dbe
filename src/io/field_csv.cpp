#include "dfvn/io/field_csv.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "dfvn/core/parallel.hpp"

namespace dfvn {

std::string field_csv(const PointTable& points, const double* velocity, const double* values, int threads) {
  const int n = points.dimension;
  const auto count = static_cast<std::int64_t>(points.rows());
  // Rows are formatted in fixed blocks and joined in order, so the output is the same for any
  // number of threads.
  constexpr std::int64_t kBlock = 4096;
  const std::int64_t blocks = (count + kBlock - 1) / kBlock;
  std::vector<std::string> text(static_cast<std::size_t>(blocks));
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolve_threads(threads))
  for (std::int64_t b = 0; b < blocks; ++b) {
    std::string& out = text[static_cast<std::size_t>(b)];
    for (std::int64_t i = b * kBlock; i < std::min(count, (b + 1) * kBlock); ++i) {
      const auto row = static_cast<std::size_t>(i);
      for (int j = 0; j < n; ++j) append_double(out, points.row(row)[j]), out += ',';
      for (int j = 0; j < n; ++j) append_double(out, velocity[row * n + j]), out += ',';
      for (int j = 0; j < n - 1; ++j) {
        append_double(out, values[row * (n - 1) + j]);
        out += (j + 2 < n) ? ',' : '\n';
      }
    }
  }
  std::string csv = numbered_header("x", n) + ',' + numbered_header("c", n) + ',' + numbered_header("f", n - 1, 1) + '\n';
  for (const auto& block : text) csv += block;
  return csv;
}

}  // namespace dfvn
