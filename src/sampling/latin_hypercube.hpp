// Latin hypercube sampling (McKay, Beckman and Conover 1979), as SciPy's qmc.LatinHypercube with its
// default scramble=True: on each axis the n points take the n strata [m/n, (m+1)/n) in a random
// order, each at a uniform random place inside its stratum.
#pragma once

#include <cstdint>

#include "dfvn/core/point_set.hpp"

namespace dfvn {

// `count` points scaled to `domain`. Axis k's stratum order is a Fisher-Yates permutation drawn from
// (seed, axis); the offsets from (seed, point, axis): deterministic per seed, independent of threads.
PointSet latin_hypercube_points(int dimension, std::uint64_t count, const Box& domain, std::uint64_t seed, int threads);

}  // namespace dfvn
