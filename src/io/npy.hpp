// NumPy .npy output (format version 1.0): float64, shape (points, N), C order; numpy.load reads it.
#pragma once

#include <ostream>

#include "sampling/point_set.hpp"

namespace dfvn {

void write_npy(std::ostream& out, const PointSet& points);

}  // namespace dfvn
