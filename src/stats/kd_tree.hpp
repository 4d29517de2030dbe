// nanoflann KD-tree over a PointSet (the points are not copied).
#pragma once

#include <nanoflann.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "dfvn/core/point_set.hpp"

namespace dfvn {

template <int N>
struct PointSetAdaptor {
  const PointSet& points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t j) const { return points.coordinates[i * N + j]; }
  template <class Bbox>
  bool kdtree_get_bbox(Bbox&) const { return false; }
};

// Distances reported by this tree are SQUARED Euclidean distances.
template <int N>
using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointSetAdaptor<N>>,
                                                   PointSetAdaptor<N>, N, std::uint32_t>;

// Leaf size 10 (nanoflann's default), for nanoflann's own searches (the RDF) and FLANN's tree; the
// nearest-neighbour statistics build their tree with stats/nearest_other.hpp's kLeafSize.
inline constexpr int kKdTreeLeafSize = 10;

// Parameters of a tree that its constructor builds (nanoflann does unless told to skip it; a further
// buildIndex() would build it a second time).
inline nanoflann::KDTreeSingleIndexAdaptorParams kd_tree_params(int leaf_size = kKdTreeLeafSize) {
  return nanoflann::KDTreeSingleIndexAdaptorParams(static_cast<std::size_t>(leaf_size));
}

}  // namespace dfvn
