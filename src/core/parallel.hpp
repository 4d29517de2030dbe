// Thread-count handling. Results never depend on the count: parallel loops write to slots indexed by
// point, and randomness is keyed by point index (core/hash.hpp).
#pragma once

#include <omp.h>

namespace dfvn {

// 0 means "all available cores".
inline int resolve_threads(int requested) { return requested > 0 ? requested : omp_get_max_threads(); }

}  // namespace dfvn
