// The unit torus [0,1)^N: coordinates taken modulo 1.
#pragma once

#include <cmath>
#include <cstddef>

namespace dfvn {

// Every coordinate into [0, 1): x - floor(x), and 0 where rounding gives 1 (a coordinate just below 0,
// whose exact image lies within an ulp of 1, i.e. of 0).
inline void wrap_to_unit_torus(double* coordinates, std::size_t count) {
  for (std::size_t k = 0; k < count; ++k) {
    const double wrapped = coordinates[k] - std::floor(coordinates[k]);
    coordinates[k] = wrapped < 1.0 ? wrapped : 0.0;
  }
}

}  // namespace dfvn
