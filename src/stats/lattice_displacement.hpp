// How far a jittered lattice moved from its sites, and how much of the lattice survives: the measures
// that tell coherent motion (a field that moves neighbours together) from disorder.
#pragma once

#include <cstdint>
#include <vector>

namespace dfvn {

struct LatticeDisplacementSummary {
  double rms = 0.0;            // sqrt(mean |u_i|^2), length units
  double median = 0.0;         // median |u_i|, length units
  double fraction_unmoved = 0.0;    // fraction of points with |u_i| < 1% of the spacing
  // RMS of |u_i - u_j| over lattice-neighbour pairs (j = i + e_a), in spacings: the relative motion
  // of neighbours. A pure translation scores 0; uniform jitter of half-width h spacings sqrt(2N/3) h.
  double neighbour_disorder = 0.0;
  // |mean_i exp(2 pi i g . u_i)|^2 averaged over the shortest reciprocal vectors g = e_a / spacing:
  // the surviving Bragg amplitude. 1 = a perfect (or rigidly translated) lattice; ~0 (plus a 1/n
  // finite-sample bias) = no residual lattice. Uniform jitter of half-width h spacings:
  // (sin(2 pi h) / (2 pi h))^2.
  double lattice_order = 0.0;
};

// displacements: K^N x N, row-major, u_i = x_i - site_i for lattice point i (mixed radix, axis 0
// fastest, as LatticeSpec::point). Only the points with `include[i]` count towards rms, median and
// fraction_unmoved (all if `include` is empty); neighbour_disorder and lattice_order use every point.
// Deterministic: sums in index order.
LatticeDisplacementSummary summarize_lattice_displacements(int dimension, int grid, double spacing,
                                                           const std::vector<double>& displacements,
                                                           const std::vector<unsigned char>& include = {});

}  // namespace dfvn
