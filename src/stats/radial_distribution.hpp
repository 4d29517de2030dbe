// Radial distribution function g(r) of a point set in a box, with translation edge correction.
#pragma once

#include <cstdint>
#include <vector>

#include "dfvn/core/progress.hpp"
#include "dfvn/core/point_set.hpp"

namespace dfvn {

struct RdfOptions {
  double r_max = 0.0;  // 0: 2.5 mean spacings, 2.5 (volume / points)^(1/N)
  int bins = 50;
  // Query points: all when the set is no larger, otherwise a seeded random subset of about this many
  // (each query still counts its pairs with every other point). 0: all points.
  std::uint64_t max_queries = 20000;
  // The torus: minimum-image distances in the box (opposite faces identified), no edge correction;
  // r_max must be below half the side (0: 2.5 mean spacings, capped at 0.499 side).
  bool periodic = false;

  void validate() const;  // throws std::invalid_argument naming the option
};

struct RdfCurve {
  std::vector<double> r;  // bin centres
  std::vector<double> g;
  double r_max = 0.0;
  std::uint64_t queries = 0;
};

// g(r) = V^2 / (q (n - 1)) * sum over ordered pairs (i in queries, j != i) with |x_i - x_j| in the bin
// of w_ij, divided by the N-ball shell volume of the bin; w_ij = 1 / prod_a (L - |x_ia - x_ja|) is the
// translation edge correction (Ohser and Stoyan 1981) for the cube of side L and volume V. For
// uniform random points E[g(r)] = 1 at every r, edges and all. (The paper's script divides by
// shell volume x n x n on a unit volume without correction, so its curves tend to 0.5 and sag.)
// Periodic: the pairs at minimum-image distance, w_ij = 1 (the torus has no edge); every coordinate
// must lie in the box.
// Independent of thread count: per-block histograms are summed in block order. `progress`: query
// points done over query points.
RdfCurve radial_distribution(const PointSet& points, const RdfOptions& options, std::uint64_t seed, int threads,
                             const FractionProgress& progress = {});

// Throws std::invalid_argument unless every g(r) of an RDF with this r_max (at most 0.999 side) and
// number of bins is finite for points in a cube of this side: a bin too narrow has a shell volume
// that underflows, and --rdf-max 1e-300 gave NaN.
void check_rdf_resolution(int dimension, double side, double r_max, int bins);

// Volume of the unit ball in N dimensions, pi^(N/2) / Gamma(N/2 + 1).
double unit_ball_volume(int dimension);

}  // namespace dfvn
