// Random jitter of a lattice and uniform random points, from a counter-based generator keyed by
// (seed, point index, axis): the output does not depend on the thread count.
#pragma once

#include <cstdint>

#include "sampling/lattice.hpp"
#include "sampling/point_set.hpp"

namespace dfvn {

// Every lattice point plus an offset uniform in [-h, h]^N, h = jitter_half_width(lattice).
// Domain: [0,1]^N (both protocols' lattices plus jitter stay inside it).
PointSet jittered_lattice(const LatticeSpec& lattice, std::uint64_t seed, int threads);
// The same with any half-width h >= 0 (length units); the domain is [0,1]^N, points may leave it.
PointSet jittered_lattice(const LatticeSpec& lattice, double half_width, std::uint64_t seed, int threads);

// `count` points uniform in `domain`.
PointSet uniform_random_points(int dimension, std::uint64_t count, const Box& domain, std::uint64_t seed, int threads);

}  // namespace dfvn
