// The regular K^N lattice that jittering starts from, per protocol.
#pragma once

#include <cstdint>
#include <vector>

#include "dfvn/core/point_set.hpp"
#include "dfvn/sampling/method.hpp"

namespace dfvn {

struct LatticeSpec {
  int dimension = 3;
  int grid = 10;  // K points per axis
  Protocol protocol = Protocol::paper;

  // K^N; throws std::invalid_argument if it does not fit in 63 bits.
  std::uint64_t point_count() const;
  // Distance between neighbouring lattice points along an axis.
  double spacing() const;
  // paper: linspace(delta/2, 1 - delta/2, K) with delta = 0.1 (so the spacing is 0.9/(K-1): 0.1 for
  // K = 10, 0.15 for K = 7, 0.18 for K = 6); unit: cell centres (i + 1/2) / K.
  double coordinate(int i) const;
  // The box the lattice's K^N cells fill, each site at the centre of its cube of side spacing():
  // [coordinate(0) - h/2, coordinate(K-1) + h/2]^N. The unit lattice's is [0,1]^N; the paper's is
  // wider than the unit cube where its spacing exceeds delta (6D, K = 7: [-0.025, 1.025]^6, 1.05^6 =
  // 1.34 times its volume; 7D, K = 6: [-0.04, 1.04]^7, 1.71 times). A jittered lattice's density is one
  // point per cell, points / this box's volume, not points / the unit cube's.
  Box cells() const;
  // Point `index` (mixed radix, axis 0 fastest) into out[0..N).
  void point(std::uint64_t index, double* out) const;
};

// x_i - site_i for a point set in lattice order (point i moved from site i): K^N x N, row-major.
std::vector<double> lattice_displacements(const LatticeSpec& lattice, const PointSet& points);

// The lattice size K >= 2 whose K^N is nearest to `count` (the smaller K on a tie): users think in
// point counts, lattices come in K^N. Throws std::invalid_argument for count 0, a dimension < 1 or K >= 2^30.
int grid_for_count(int dimension, std::uint64_t count);

// Half-width of the uniform jitter: paper: delta/2 = 0.05 whatever K (data/PROTOCOL.md); unit: 1/(2K).
double jitter_half_width(const LatticeSpec& lattice);

// The paper's delta = 0.1, the lattice step for K = 10 and the PDS radius of Table 1.
inline constexpr double kPaperDelta = 0.1;

// Section 5.1: the average distance from a lattice point to its 3^N - 1 neighbours, in units of the
// spacing: dbar = sum_{i=1..N} 2^i C(N, i) sqrt(i) / (3^N - 1). (C(N,i) 2^i neighbours differ in i
// coordinates, by +-1 each, and lie sqrt(i) away.)
double average_neighbour_distance(int dimension);

}  // namespace dfvn
