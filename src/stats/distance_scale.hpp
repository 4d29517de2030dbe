// Distance statistics at any scale. The KD-trees compare SQUARED distances, and the RDF and the scaled
// median use the domain's volume side^N; in doubles both overflow for sets of side near 1e154 (or 1e38
// for side^8) and underflow near 1e-154, which gave crashes (a KD-tree fed Inf) and Inf/NaN statistics
// (issue 23). The entry points therefore compute on the set divided by a power of two, which is exact:
// every difference, square and square root scales by a power of two (of four under the root) and
// rounds as before, so results are the same bits as an unscaled computation would give where that one
// does not overflow, and sets of ordinary size are not copied at all.
#pragma once

#include <string_view>
#include <vector>

#include "dfvn/core/point_set.hpp"

namespace dfvn {

// The domains statistics accept: sides in [2^-1000, 2^1000] (about 9.3e-302 to 1.07e301). Above,
// sqrt(N) side, the longest nearest-neighbour distance, approaches DBL_MAX; below, points in the
// domain are subnormal numbers with fewer than 53 bits.
inline constexpr double kMinDomainSide = 0x1p-1000;
inline constexpr double kMaxDomainSide = 0x1p1000;

// Throws std::invalid_argument unless side is in [kMinDomainSide, kMaxDomainSide]; `what` names it
// in the message ("the domain side").
void check_domain_side(double side, std::string_view what = "the domain side");

// The power of two to divide coordinates by before squaring differences: 1 when the largest |x| is
// in [2^-256, 2^256] (no sum of N squared differences can overflow, none of ordinary resolution
// underflows), otherwise 2^floor(log2 max|x|). Throws std::invalid_argument naming the first
// coordinate that is not finite.
double coordinate_scale(const PointSet& points);

// The power of two to divide the domain's side by before taking volumes: 1 for sides in
// [2^-32, 2^32] (volume^2 of an 8D cube stays in range), otherwise 2^floor(log2 side).
double domain_scale(double side);

// The set with every coordinate and its domain divided by `scale` (a power of two: exact).
PointSet scaled_point_set(const PointSet& points, double scale);

// Nearest-neighbour distances below 2^-510 times coordinate_scale(points) come from squared
// distances near or below the smallest normal double, where the KD-tree cannot tell neighbours apart:
// such a distance is only exact for a duplicate point (distance 0). Throws std::invalid_argument
// naming the first point whose distance is that small and that has no exact duplicate.
void check_nearest_neighbours_resolved(const PointSet& points, const std::vector<double>& distances);
inline constexpr double kMinResolvedDistance = 0x1p-510;

}  // namespace dfvn
