#include "dfvn/field/evaluate_points.hpp"

#include <algorithm>
#include <cstdint>

#include <fmt/format.h>

#include "dfvn/core/parallel.hpp"
#include "dfvn/field/dfvn_field.hpp"
#include "dfvn/noise/noise_domain.hpp"

namespace dfvn {

void evaluate_field(const FieldQuery& query, const double* points, std::size_t rows, double* velocity, double* values,
                    const FractionProgress& progress) {
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
      // The first thread's static block is rows [0, rows / threads): its share done stands for all.
      if (progress && omp_get_thread_num() == 0 && row % 1024 == 0)
        progress(std::min(1.0, static_cast<double>(row) * omp_get_num_threads() / static_cast<double>(rows)));
    }
    if (progress) progress(1.0);
  });
}

}  // namespace dfvn
