// How far a jittered lattice moved from its sites, and how much of the lattice survives: the measures
// that tell coherent motion (a field that moves neighbours together) from disorder.
#pragma once

#include <complex>
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
// Deterministic: sums in index order, the same bits for any `threads` (the axes' sums and the lengths'
// pass run side by side, each in one thread, from 2^20 coordinates on).
LatticeDisplacementSummary summarize_lattice_displacements(int dimension, int grid, double spacing,
                                                           const std::vector<double>& displacements,
                                                           const std::vector<unsigned char>& include = {},
                                                           int threads = 1);

// The sums behind the summary, each a sum in index order (per axis for the neighbour pairs and the Bragg
// amplitudes), so that a run made in slabs of whole layers (experiment/streamed_sampling.hpp) adds the same
// terms in the same order; finish_lattice_displacements turns them and the median of the lengths into the
// summary exactly as summarize_lattice_displacements does.
struct LatticeDisplacementSums {
  std::uint64_t points = 0;    // every row
  std::uint64_t included = 0;  // rows counted in rms, median and fraction_unmoved
  double sum2 = 0.0;           // sum of |u_i|^2 over the included rows
  std::uint64_t unmoved = 0;   // included rows with |u_i| < 1% of the spacing
  std::vector<double> pair_sum2;               // per axis: sum of |u_i - u_j|^2 over its neighbour pairs
  std::uint64_t pairs = 0;                     // neighbour pairs over every axis
  std::vector<std::complex<double>> bragg;     // per axis: sum of exp(2 pi i u_i[a] / spacing)
};
LatticeDisplacementSummary finish_lattice_displacements(int dimension, double spacing, const LatticeDisplacementSums& sums,
                                                        double median_length);

}  // namespace dfvn
