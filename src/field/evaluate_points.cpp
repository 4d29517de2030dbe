#include "field/evaluate_points.hpp"

#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "core/parallel.hpp"
#include "field/dfvn_field.hpp"
#include "noise/noise_domain.hpp"

namespace dfvn {

std::string evaluate_field_csv(const FieldQuery& query, const PointTable& points) {
  if (points.dimension != query.dimension)
    throw std::invalid_argument("point table has dimension " + std::to_string(points.dimension) +
                                ", query has " + std::to_string(query.dimension));
  check_thread_count(query.threads);
  return dispatch_dimension(query.dimension, [&]<int N>() {
    const DfvnField<N> field(query.seed, query.field);
    // Checked here, not in the parallel loop: an exception must not escape an OpenMP region.
    for (std::size_t i = 0; i < points.rows(); ++i) {
      const Vec<N> x = Eigen::Map<const Vec<N>>(points.row(i));
      if (!field.in_domain(x)) field.check_in_domain(x, fmt::format("point {}", i + 1));
    }
    const auto rows = static_cast<std::int64_t>(points.rows());
    // Rows are formatted in fixed blocks and joined in order, so the output is the same for any
    // number of threads.
    constexpr std::int64_t kBlock = 4096;
    const std::int64_t blocks = (rows + kBlock - 1) / kBlock;
    std::vector<std::string> text(static_cast<std::size_t>(blocks));
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolve_threads(query.threads))
    for (std::int64_t b = 0; b < blocks; ++b) {
      std::string& out = text[static_cast<std::size_t>(b)];
      for (std::int64_t i = b * kBlock; i < std::min(rows, (b + 1) * kBlock); ++i) {
        const Vec<N> x = Eigen::Map<const Vec<N>>(points.row(static_cast<std::size_t>(i)));
        const FieldSample<N> s = field.evaluate(x);
        for (int j = 0; j < N; ++j) append_double(out, x[j]), out += ',';
        for (int j = 0; j < N; ++j) append_double(out, s.velocity[j]), out += ',';
        for (int j = 0; j < N - 1; ++j) {
          append_double(out, s.value[j]);
          out += (j + 2 < N) ? ',' : '\n';
        }
      }
    }
    std::string csv = numbered_header("x", N) + ',' + numbered_header("c", N) + ',' + numbered_header("f", N - 1, 1) + '\n';
    for (const auto& block : text) csv += block;
    return csv;
  });
}

}  // namespace dfvn
