// Random jitter of a lattice and uniform random points, from a counter-based generator keyed by
// (seed, point index, axis): the output does not depend on the thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "dfvn/sampling/lattice.hpp"
#include "dfvn/core/point_set.hpp"

namespace dfvn {

// Every lattice point plus an offset uniform in [-h, h]^N, h = jitter_half_width(lattice).
// Domain: [0,1]^N (both protocols' lattices plus jitter stay inside it).
PointSet jittered_lattice(const LatticeSpec& lattice, std::uint64_t seed, int threads);
// The same with any half-width h >= 0 (length units); the domain is [0,1]^N, points may leave it.
PointSet jittered_lattice(const LatticeSpec& lattice, double half_width, std::uint64_t seed, int threads);

// Stratified jitter in the unit ball of the lattice's cube (centre 1/2, radius 1/2): the sites strictly
// inside it (CNJ's start set in the ball, in lattice order), each plus an offset uniform in [-h, h]^N, h =
// jitter_half_width(lattice); an offset that leaves the ball is drawn again (from the words of (seed,
// site, attempt)), up to 4096 times, after which the point stays at its site. Domain: that ball.
PointSet jittered_sites_in_ball(const LatticeSpec& lattice, std::uint64_t seed, int threads);

// How jitter keeps a lattice in the unit cube when an offset reaches past a face: wrap (the torus
// [0,1)^N, every coordinate taken modulo 1) or reflect (the cube [0,1]^N, folded back at the face as
// a mirror would: the face then acts like a mirror plane of the jittered lattice).
enum class JitterBoundary { wrap, reflect };

// Jitter that moves a lattice exactly as far as another method did: lattice point i plus a v_i, with
// v_i the offsets of jittered_lattice (uniform in [-1, 1]^N, the same draws for the same seed) and the
// half-width a chosen so that the RMS displacement sqrt(mean_i |x_i - site_i|^2) equals `rms` (to
// rounding). wrap: the displacement is a v_i (before wrapping), so a = rms / sqrt(mean |v_i|^2);
// reflect: a reflected displacement is shorter, and a is found by bisection. Throws
// std::invalid_argument for an rms that is not finite and positive, or that reflection in the unit
// cube cannot reach.
struct MatchedJitter {
  PointSet points;
  double half_width = 0.0;            // a, length units
  std::vector<double> displacements;  // x_i - site_i (before wrapping), K^N x N row-major
};
MatchedJitter jitter_matching_rms(const LatticeSpec& lattice, double rms, JitterBoundary boundary, std::uint64_t seed,
                                  int threads);

// `count` points uniform in `domain`.
PointSet uniform_random_points(int dimension, std::uint64_t count, const Box& domain, std::uint64_t seed, int threads);
// Points first .. first + count - 1 of those sets (the same bits as the whole set's rows): the slabs of
// a streamed run (experiment/streamed_sampling.hpp).
PointSet jittered_lattice_range(const LatticeSpec& lattice, double half_width, std::uint64_t first, std::uint64_t count,
                                std::uint64_t seed, int threads);
PointSet uniform_random_points_range(int dimension, std::uint64_t first, std::uint64_t count, const Box& domain,
                                     std::uint64_t seed, int threads);

}  // namespace dfvn
