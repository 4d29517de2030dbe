// The `field` command's table: points with the field's vector and noise values at each, as CSV.
#pragma once

#include <string>

#include "dfvn/io/csv.hpp"

namespace dfvn {

// CSV with header x0..x{N-1},c0..c{N-1},f1..f{N-1} and one row per point of `points` (N columns): the
// point, velocity (rows x N, row-major: the field vector c(x)) and values (rows x (N-1), row-major: the
// noise values f_i(x)), each with 17 significant digits. The bytes do not depend on `threads`.
std::string field_csv(const PointTable& points, const double* velocity, const double* values, int threads);

}  // namespace dfvn
