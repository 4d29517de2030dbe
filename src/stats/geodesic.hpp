// Nearest-neighbour statistics of points on the unit sphere, in great-circle (geodesic) distance.
#pragma once

#include <vector>

#include "dfvn/core/point_set.hpp"
#include "dfvn/stats/nearest_neighbour.hpp"

namespace dfvn {

// For every point (a unit vector), the angle to its nearest other point. The angle 2 asin(chord / 2)
// grows with the chord |x - y|, so the Euclidean nearest neighbour of the KD-tree is the geodesic one.
std::vector<double> geodesic_nearest_neighbour_distances(const PointSet& points, KnnBackend backend, int threads);

// Brute force, O(n^2), acos(x . y) over all pairs: the reference for the KD-tree route.
std::vector<double> geodesic_nearest_neighbour_distances_brute_force(const PointSet& points);

// The summary with median_scaled = median * (points / area(S^{N-1}))^(1/(N-1)).
NearestNeighbourSummary summarize_geodesic_nearest_neighbours(std::vector<double> angles, int dimension);

}  // namespace dfvn
