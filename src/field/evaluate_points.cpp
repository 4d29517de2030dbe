#include "field/evaluate_points.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "core/parallel.hpp"
#include "field/dfvn_field.hpp"
#include "noise/noise_domain.hpp"

namespace dfvn {

void evaluate_field(const FieldQuery& query, const double* points, std::size_t rows, double* velocity, double* values) {
  check_thread_count(query.threads);
  dispatch_dimension(query.dimension, [&]<int N>() {
    const DfvnField<N> field(query.seed, query.field);
    // Checked here, not in the parallel loop: an exception must not escape an OpenMP region.
    for (std::size_t i = 0; i < rows; ++i) {
      const Vec<N> x = Eigen::Map<const Vec<N>>(points + i * N);
      if (!field.in_domain(x)) field.check_in_domain(x, fmt::format("point {}", i + 1));
    }
    // Every row is written to its own slots, so the numbers are the same for any number of threads.
#pragma omp parallel for schedule(static) num_threads(resolve_threads(query.threads))
    for (std::int64_t i = 0; i < static_cast<std::int64_t>(rows); ++i) {
      const auto row = static_cast<std::size_t>(i);
      const FieldSample<N> s = field.evaluate(Eigen::Map<const Vec<N>>(points + row * N));
      Eigen::Map<Vec<N>>(velocity + row * N) = s.velocity;
      std::copy(s.value.begin(), s.value.end(), values + row * (N - 1));
    }
  });
}

std::string evaluate_field_csv(const FieldQuery& query, const PointTable& points) {
  if (points.dimension != query.dimension)
    throw std::invalid_argument("point table has dimension " + std::to_string(points.dimension) +
                                ", query has " + std::to_string(query.dimension));
  const int n = query.dimension;
  const std::size_t rows = points.rows();
  std::vector<double> velocity(rows * n), values(rows * (n - 1));
  evaluate_field(query, points.coordinates.data(), rows, velocity.data(), values.data());
  const auto count = static_cast<std::int64_t>(rows);
  // Rows are formatted in fixed blocks and joined in order, so the output is the same for any
  // number of threads.
  constexpr std::int64_t kBlock = 4096;
  const std::int64_t blocks = (count + kBlock - 1) / kBlock;
  std::vector<std::string> text(static_cast<std::size_t>(blocks));
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolve_threads(query.threads))
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
