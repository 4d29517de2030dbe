// The exact nearest OTHER point of every point of a set that fills its torus [lo, lo + side)^N about evenly
// (blue noise, jittered lattices, low-discrepancy and uniform random sets), in a grid of about one point
// per cell: private to stats/ (not installed). The periodic statistics (stats/periodic_neighbours.cpp) try
// it first and use the KD-tree search (stats/nearest_other.hpp) when it declines.
//
// Why: on the torus the KD-tree search costs 4-5x its Euclidean form in 7D (92% of the main job's points lie
// within a nearest distance of some face, and every way round must be searched), and its leaves of 64
// points scan thousands of points per query where a grid of one point per cell reaches the
// nearest point in a few hundred cells. The grid walks depth first over all axes but the last, nearer
// cells of each axis first, into the lines of cells along the last axis whose box comes within the best
// distance found so far (the cells wrap round the torus), and scans a whole line, 8 points to a vector.
//
// The answer is the KD-tree search's, bit for bit: for each query the square root of the smallest squared
// distance over the other points, each summed over axes in order of minimum-image differences as
// periodic_distance_between() sums them. A line is skipped only when its lower bound, less a slack far
// above its rounding, exceeds the best squared distance by the KD-tree's relative margin (1e-9).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "dfvn/core/point_set.hpp"
#include "dfvn/core/progress.hpp"
#include "dfvn/core/simd.hpp"

namespace dfvn::cell_grid {

// distances[i] = the minimum-image distance from point i to its nearest other point, for the first `queries`
// points, on the torus [lo, lo + side)^N of points.domain; every coordinate in [lo, lo + side] (checked by
// the caller), at unit scale. std::nullopt when the grid would be slow for this set: fewer than 4 axes or 4
// cells per axis, a cell holding more than 32 points (a clustered set, or one that fills a small part of
// the torus), or 2^31 points or more. Parallel over chunks of lines; the same values for any thread count.
// `simd`: the widest build this CPU runs (best) or the baseline (the tests compare them: the same bits).
std::optional<std::vector<double>> periodic_nearest_distances(const PointSet& points, std::size_t queries, int threads,
                                                              const FractionProgress& progress, Simd simd = Simd::best);

}  // namespace dfvn::cell_grid
