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

// Leaf size 10 (nanoflann's default), for nanoflann's own searches (periodic neighbours, the RDF); the
// Euclidean nearest-neighbour statistics build their tree with stats/nearest_other.hpp's kLeafSize.
inline constexpr int kKdTreeLeafSize = 10;

// Parameters of a tree that its constructor builds (nanoflann does unless told to skip it; a further
// buildIndex() would build it a second time).
inline nanoflann::KDTreeSingleIndexAdaptorParams kd_tree_params(int leaf_size = kKdTreeLeafSize) {
  return nanoflann::KDTreeSingleIndexAdaptorParams(static_cast<std::size_t>(leaf_size));
}

// Rows of N doubles whose storage may move after the tree is built (LeafOrderedTree).
template <int N>
struct RowsAdaptor {
  const double* rows = nullptr;
  std::size_t count = 0;
  std::size_t kdtree_get_point_count() const { return count; }
  double kdtree_get_pt(std::size_t i, std::size_t j) const { return rows[i * N + j]; }
  template <class Bbox>
  bool kdtree_get_bbox(Bbox&) const { return false; }
};

// A KD-tree over a copy of the points stored in the tree's leaf order: row k of sorted() is input point
// original()[k], the points of each leaf are consecutive rows, and the tree's indices are rows. Queries
// made row after row walk the same nodes and leaves as their predecessors and find their rows in cache:
// for point sets in no spatial order (Sobol, Poisson disk) this is several times faster than querying by
// input index over scattered rows (bench/results.md). Distances computed from the rows are the same bits
// as from the input: the rows are the same numbers.
template <int N>
class LeafOrderedTree {
 public:
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, RowsAdaptor<N>>, RowsAdaptor<N>, N,
                                                   std::uint32_t>;
  explicit LeafOrderedTree(const PointSet& points, int leaf_size = kKdTreeLeafSize)
      : adaptor_{points.coordinates.data(), points.size()}, tree_(N, adaptor_, kd_tree_params(leaf_size)) {
    original_ = tree_.vAcc;
    sorted_ = PointSet{N, Coordinates(points.coordinates.size()), points.domain};
    for (std::size_t k = 0; k < original_.size(); ++k)
      std::copy_n(points.point(original_[k]), N, sorted_.coordinates.data() + k * N);
    adaptor_.rows = sorted_.coordinates.data();
    for (std::size_t k = 0; k < tree_.vAcc.size(); ++k) tree_.vAcc[k] = static_cast<std::uint32_t>(k);
  }
  LeafOrderedTree(const LeafOrderedTree&) = delete;
  LeafOrderedTree& operator=(const LeafOrderedTree&) = delete;

  const Tree& tree() const { return tree_; }
  const PointSet& sorted() const { return sorted_; }
  const std::vector<std::uint32_t>& original() const { return original_; }

 private:
  RowsAdaptor<N> adaptor_;
  Tree tree_;
  PointSet sorted_;
  std::vector<std::uint32_t> original_;
};

}  // namespace dfvn
