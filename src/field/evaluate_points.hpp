// The `field` command's work: evaluate the DFVN field at a table of points (io/field_csv.hpp writes it).
#pragma once

#include <cstddef>
#include <cstdint>

#include "dfvn/core/progress.hpp"
#include "dfvn/field/dfvn_field.hpp"

namespace dfvn {

struct FieldQuery {
  int dimension = 3;
  std::uint64_t seed = 1;
  FieldOptions field;  // noise basis and frequency
  int threads = 0;  // 0: all cores
};

// The field at `rows` points (points: rows x N, row-major): velocity (rows x N, row-major) receives
// c(x) and values (rows x (N-1), row-major) the noise values f_i(x). The numbers do not depend on the
// thread count. Throws std::invalid_argument, naming the point (1-based) and column, when frequency *
// coordinate is outside the noise domain (noise/noise_domain.hpp), NaN included; nothing is written then.
// `progress`: rows done over rows.
void evaluate_field(const FieldQuery& query, const double* points, std::size_t rows, double* velocity, double* values,
                    const FractionProgress& progress = {});

}  // namespace dfvn
