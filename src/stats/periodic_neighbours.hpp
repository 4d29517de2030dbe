// Nearest-neighbour distances on the torus: the points' box [lo, lo + side)^N with opposite faces
// identified, measured with minimum-image distances (as UTK measures its periodic samplers, and as a
// point set made on the torus should be measured).
#pragma once

#include <cstddef>
#include <vector>

#include "dfvn/core/progress.hpp"
#include "dfvn/core/point_set.hpp"

namespace dfvn {

// The minimum-image distance between points i and j: sqrt(sum_a m(x_ia - x_ja)^2) with
// m(d) = d - side round(d / side), summed over axes in order.
double periodic_distance_between(const PointSet& points, std::size_t i, std::size_t j);

// For every point, the minimum-image distance to its nearest other point: the smallest of
// periodic_distance_between over j != i. Every coordinate must lie in [lo, lo + side] (throws
// std::invalid_argument naming the first that does not); needs at least 2 points. 1D by sorting;
// 4D-8D sets that fill the torus about evenly by a grid of about one point per cell
// (stats/cell_grid_neighbours.hpp); the others by an exact KD-tree walk in which a subtree is as near as
// the way round through the opposite face allows (stats/nearest_other.hpp). Both give the same bits.
// Independent of the thread count. `progress`: points (or lines of grid cells) done over all.
std::vector<double> periodic_nearest_neighbour_distances(const PointSet& points, int threads,
                                                         const FractionProgress& progress = {});

// The same distances for the first `queries` points only, each to its nearest other point among ALL the
// points (the tree is built over every point, only the first `queries` are queried): bit for bit
// periodic_nearest_neighbour_distances(points, ...)'s values for those points. Needs at least 2 points and
// queries <= size() (queries = 0 gives no distances). Independent of thread count.
std::vector<double> periodic_nearest_neighbour_distances_of_first(const PointSet& points, std::size_t queries,
                                                                  int threads, const FractionProgress& progress = {});

// Brute force, O(n^2): the reference the KD-tree version is tested against.
std::vector<double> periodic_nearest_neighbour_distances_brute_force(const PointSet& points);

// Throws std::invalid_argument unless every coordinate lies in [lo, lo + side].
void check_in_periodic_box(const PointSet& points);

}  // namespace dfvn
