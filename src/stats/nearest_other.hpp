// The exact nearest OTHER point of every point of a nanoflann KD-tree (stats/kd_tree.hpp), private to
// stats/: a search specialised for that one question (k = 1 with the point itself excluded, the dimension
// a template parameter, no per-query allocation, no recursion) over a flat copy of nanoflann's tree.
// Rows are queried leaf after leaf; each query first takes its nearest point within its own leaf and
// within the leaf where the previous query found its nearest point (a tight radius before the descent)
// and skips those leaves later; a leaf that the descent reaches is scanned only if its bounding box is
// within the radius. Leaves store their points four to a block,
// coordinate by coordinate, so that one vector instruction takes a coordinate of four points.
//
// The answer is the same as nanoflann's k = 2 self-query: the minimum over the other points of the
// squared distance summed over axes in order, each (x - q)^2 rounded as distance_between() rounds it
// (every lane sums its own axes in order; no fused multiply-adds: see CMakeLists.txt), so the distance
// of the row found is the same bits whichever of two tied rows is found. A subtree or leaf is pruned only
// when its lower bound exceeds the best squared distance by a relative margin (1e-9) far above the bound's
// rounding (a few units in the last place), so no closer point is ever pruned.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "dfvn/core/point_set.hpp"
#include "dfvn/core/simd.hpp"
#include "dfvn/stats/kd_tree.hpp"

namespace dfvn::nearest_other {

inline constexpr int kLanes = 4;
// Leaves of up to 32 points: with four points to a vector a leaf costs little more to scan than a node
// to pass, and fewer, larger leaves mean fewer nodes per query. Against 10 (nanoflann's default, kept by
// the other trees of stats/), the 7D main job's sets took 1.6-2x less CPU time in this search; 24-48 were
// alike, and 2D-5D sets of 2^18 points were no slower (bench/results.md).
inline constexpr int kLeafSize = 32;
inline constexpr double kPruneMargin = 1.0 + 1e-9;

template <int N>
class Index {
 public:
  struct Node {
    std::int32_t child1 = -1, child2 = -1;  // -1: a leaf
    std::int32_t cut = 0;                   // internal: the axis cut
    std::uint32_t leaf = 0;                 // a leaf's index in leaves()
    double low = 0.0, high = 0.0;           // internal: child1's points lie at or below low, child2's at or above high
  };
  struct Leaf {
    std::uint32_t first = 0, count = 0;  // rows [first, first + count)
    std::uint32_t block = 0;             // its first block of kLanes points (ceil(count / kLanes) blocks)
    std::uint32_t node = 0;              // its node
  };

  // `tree`: built over `points` (both must outlive the index); its leaves' points are copied in leaf order.
  Index(const PointSet& points, const KdTree<N>& tree) : original_(tree.vAcc.data()) {
    convert(tree.root_node, 1);
    // nanoflann numbers its leaves' points depth first: leaf after leaf, consecutive rows (the callers rely on it).
    for (std::size_t l = 1; l < leaves_.size(); ++l)
      if (leaves_[l].first != leaves_[l - 1].first + leaves_[l - 1].count) throw std::logic_error("KD-tree leaves out of row order");
    std::size_t blocks = 0;
    for (const Leaf& leaf : leaves_) blocks += (leaf.count + kLanes - 1) / kLanes;
    blocks_ = Coordinates(blocks * N * kLanes);  // without zero-fill, on huge pages when large (core/bulk_memory.hpp)
    for (const Leaf& leaf : leaves_)
      for (std::uint32_t j = 0; j < (leaf.count + kLanes - 1) / kLanes * kLanes; ++j) {
        double* block = blocks_.data() + (leaf.block + j / kLanes) * N * kLanes;
        const double* x = j < leaf.count ? points.point(original_[leaf.first + j]) : nullptr;
        for (int k = 0; k < N; ++k)  // padding lanes at +inf: their squared distance is +inf, never a minimum
          block[k * kLanes + j % kLanes] = x ? x[k] : std::numeric_limits<double>::infinity();
      }
    leaf_of_row_.resize(leaves_.empty() ? 0 : leaves_.back().first + leaves_.back().count);
    for (std::size_t l = 0; l < leaves_.size(); ++l)
      std::fill_n(leaf_of_row_.begin() + leaves_[l].first, leaves_[l].count, static_cast<std::uint32_t>(l));
    leaf_boxes_.assign(leaves_.size() * 2 * kBoxLanes, 0.0);
    for (std::size_t l = 0; l < leaves_.size(); ++l) {
      double* box = leaf_boxes_.data() + l * 2 * kBoxLanes;
      for (int k = 0; k < N; ++k) box[k] = std::numeric_limits<double>::infinity(), box[kBoxLanes + k] = -box[k];
      for (std::uint32_t r = leaves_[l].first; r < leaves_[l].first + leaves_[l].count; ++r)
        for (int k = 0; k < N; ++k) {
          const double x = points.point(original_[r])[k];
          box[k] = std::min(box[k], x), box[kBoxLanes + k] = std::max(box[kBoxLanes + k], x);
        }
    }
  }
  Index(const Index&) = delete;
  Index& operator=(const Index&) = delete;

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<Leaf>& leaves() const { return leaves_; }
  // Row r (the rows are the leaves' points, leaf after leaf) is input point original()[r].
  const std::uint32_t* original() const { return original_; }
  const double* blocks() const { return blocks_.data(); }
  // Leaf l's bounding box: N lower coordinates padded with zeros to kBoxLanes, then the N upper ones.
  static constexpr int kBoxLanes = (N + kLanes - 1) / kLanes * kLanes;
  const double* leaf_box(std::size_t l) const { return leaf_boxes_.data() + l * 2 * kBoxLanes; }
  const std::uint32_t* leaf_of_row() const { return leaf_of_row_.data(); }
  int depth() const { return depth_; }
  std::uint32_t largest_leaf() const { return largest_leaf_; }

 private:
  using TreeNode = typename KdTree<N>::Node;

  // Copies the subtree of `node`; returns its index.
  std::uint32_t convert(const TreeNode* node, int depth) {
    depth_ = std::max(depth_, depth);
    const auto self = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    if (node->child1 == nullptr && node->child2 == nullptr) {
      Leaf leaf;
      leaf.first = static_cast<std::uint32_t>(node->node_type.lr.left);
      leaf.count = static_cast<std::uint32_t>(node->node_type.lr.right - node->node_type.lr.left);
      leaf.block = leaves_.empty() ? 0 : leaves_.back().block + (leaves_.back().count + kLanes - 1) / kLanes;
      leaf.node = self;
      largest_leaf_ = std::max(largest_leaf_, leaf.count);
      nodes_[self].leaf = static_cast<std::uint32_t>(leaves_.size());
      leaves_.push_back(leaf);
      return self;
    }
    nodes_[self].cut = node->node_type.sub.divfeat;
    nodes_[self].low = node->node_type.sub.divlow;
    nodes_[self].high = node->node_type.sub.divhigh;
    const std::uint32_t a = convert(node->child1, depth + 1);
    const std::uint32_t b = convert(node->child2, depth + 1);
    nodes_[self].child1 = static_cast<std::int32_t>(a);
    nodes_[self].child2 = static_cast<std::int32_t>(b);
    return self;
  }

  const std::uint32_t* original_;
  std::vector<Node> nodes_;
  std::vector<Leaf> leaves_;
  Coordinates blocks_;
  std::vector<double> leaf_boxes_;
  std::vector<std::uint32_t> leaf_of_row_;
  int depth_ = 0;
  std::uint32_t largest_leaf_ = 0;
};

// GCC's generic vectors: two SSE2 instructions each in the baseline build, one AVX instruction each in
// the function built for AVX2 that this code is inlined into.
typedef double Vec4 __attribute__((vector_size(kLanes * sizeof(double))));

// The squared distance from point q (kBoxLanes coordinates, zero-padded) to the box `box` (Index::leaf_box),
// summed in no particular order.
template <int N>
[[gnu::always_inline]] inline double box_distance(const double* q, const double* box) {
  constexpr int kBox = Index<N>::kBoxLanes;
  Vec4 sum = {};
  for (int v = 0; v < kBox; v += kLanes) {
    Vec4 lo, hi, qv;
    std::memcpy(&lo, box + v, sizeof lo);
    std::memcpy(&hi, box + kBox + v, sizeof hi);
    std::memcpy(&qv, q + v, sizeof qv);
    const Vec4 below = lo - qv, above = qv - hi;
    Vec4 gap = below > above ? below : above;
    gap = gap > Vec4{} ? gap : Vec4{};
    sum = sum + gap * gap;
  }
  return (sum[0] + sum[1]) + (sum[2] + sum[3]);
}

// A subtree left for later: its root, the lower bound of its squared distance, and that bound's terms per axis.
template <int N>
struct StackEntry {
  std::int32_t node;
  double bound;
  double offset[N];
};

// Scratch for one thread: the subtrees left for later (each node on a path leaves at most one).
template <int N>
struct Scratch {
  std::vector<StackEntry<N>> stack;
};

// nearest[r - leaves[begin].first] = the row of a nearest other point of row r, for the rows of leaves
// [begin, end) whose input point is one of the first `queries` (original()[r] < queries); the other rows
// are not queried and their slots are left as they were. The lower bound of a subtree's squared distance
// is the sum over axes of the squared distance to the cut planes that bound it (Arya and Mount's
// incremental distance, as nanoflann's). Each row's answer is exact, so it does not depend on which rows
// were queried before it (the warm start only tightens the radius sooner).
template <int N>
[[gnu::always_inline]] inline void nearest_rows(const Index<N>& index, std::size_t begin, std::size_t end,
                                                std::uint32_t queries, std::uint32_t* nearest, Scratch<N>& s) {
  const auto* nodes = index.nodes().data();
  const auto* leaves = index.leaves().data();
  const double* blocks = index.blocks();
  const std::uint32_t base = leaves[begin].first;
  StackEntry<N>* stack = s.stack.data();
  const std::uint32_t* leaf_of_row = index.leaf_of_row();
  const std::uint32_t* original = index.original();
  std::uint32_t warm = static_cast<std::uint32_t>(begin);  // the leaf of the previous query's nearest point
  for (std::size_t a = begin; a < end; ++a) {
    const auto& own = leaves[a];
    for (std::uint32_t r = own.first; r < own.first + own.count; ++r) {
      if (original[r] >= queries) continue;
      constexpr int kBox = Index<N>::kBoxLanes;
      alignas(32) double q[kBox] = {};  // padded with zeros, as the leaves' boxes
      const std::uint32_t j = r - own.first;
      for (int k = 0; k < N; ++k) q[k] = blocks[(static_cast<std::size_t>(own.block) + j / kLanes) * N * kLanes + k * kLanes + j % kLanes];
      double best = std::numeric_limits<double>::infinity();
      std::uint32_t best_row = r;
      double limit = best;
      // The points of leaf l (but row r) that are nearer than best.
      const auto scan = [&](std::uint32_t l) {
        const auto& leaf = leaves[l];
        const std::uint32_t count = (leaf.count + kLanes - 1) / kLanes;
        const double* first_block = blocks + static_cast<std::size_t>(leaf.block) * N * kLanes;
        for (std::uint32_t b = 0; b < count; ++b) {
          const double* x = first_block + b * N * kLanes;
          Vec4 v, acc;
          for (int k = 0; k < N; ++k) {
            std::memcpy(&v, x + k * kLanes, sizeof v);  // an unaligned load (no function returns a vector)
            const Vec4 d = v - q[k];
            acc = k == 0 ? d * d : acc + d * d;  // d * d, not 0 + d * d: the same bits either way
          }
          if (std::min(std::min(acc[0], acc[1]), std::min(acc[2], acc[3])) >= best) continue;
          for (int lane = 0; lane < kLanes; ++lane) {
            const std::uint32_t row = leaf.first + b * kLanes + static_cast<std::uint32_t>(lane);
            if (acc[lane] < best && row != r) best = acc[lane], best_row = row, limit = best * kPruneMargin;
          }
        }
      };
      // The own leaf first, then the leaf where the previous query found its nearest point: a tight radius
      // before the descent, which skips both.
      scan(static_cast<std::uint32_t>(a));
      const bool warm_start = warm != a && box_distance<N>(q, index.leaf_box(warm)) <= limit;
      if (warm_start) scan(warm);
      int top = 0;
      std::int32_t node = 0;
      double bound = 0.0;
      double offset[N] = {};
      for (;;) {
        // Down the nearer child, leaving the farther for later, to a leaf.
        while (nodes[node].child1 >= 0) {
          const auto& nd = nodes[node];
          const double value = q[nd.cut];
          const double diff1 = value - nd.low, diff2 = value - nd.high;
          std::int32_t first, other;
          double cut;
          if (diff1 + diff2 < 0) {
            first = nd.child1, other = nd.child2, cut = diff2 * diff2;
          } else {
            first = nd.child2, other = nd.child1, cut = diff1 * diff1;
          }
          const double other_bound = bound + cut - offset[nd.cut];
          if (other_bound <= limit) {
            StackEntry<N>& e = stack[top++];
            e.node = other;
            e.bound = other_bound;
            std::memcpy(e.offset, offset, sizeof offset);
            e.offset[nd.cut] = cut;
          }
          node = first;
        }
        // A leaf's bounding box first: its squared distance (summed in any order) is at most any of its points'.
        if (const std::uint32_t l = nodes[node].leaf; l != a && !(warm_start && l == warm) &&
                                                      box_distance<N>(q, index.leaf_box(l)) <= limit)
          scan(l);
        for (;;) {  // the deepest subtree left that may still hold a nearer point
          if (top == 0) goto done;
          const StackEntry<N>& e = stack[--top];
          if (e.bound <= limit) {
            node = e.node;
            bound = e.bound;
            std::memcpy(offset, e.offset, sizeof offset);
            break;
          }
        }
      }
    done:
      nearest[r - base] = best_row;
      warm = leaf_of_row[best_row];
    }
  }
}

template <int N>
void nearest_rows_baseline(const Index<N>& index, std::size_t begin, std::size_t end, std::uint32_t queries,
                           std::uint32_t* nearest, Scratch<N>& s) {
  nearest_rows(index, begin, end, queries, nearest, s);
}

#if defined(__x86_64__)
template <int N>
[[gnu::target("avx2")]] void nearest_rows_avx2(const Index<N>& index, std::size_t begin, std::size_t end,
                                               std::uint32_t queries, std::uint32_t* nearest, Scratch<N>& s) {
  nearest_rows(index, begin, end, queries, nearest, s);
}
#endif

template <int N>
using NearestRows = void (*)(const Index<N>&, std::size_t, std::size_t, std::uint32_t, std::uint32_t*, Scratch<N>&);

// The widest build this CPU runs (core/simd.hpp); both give the same rows' distances.
template <int N>
NearestRows<N> nearest_rows_kernel(Simd simd) {
#if defined(__x86_64__)
  if (simd == Simd::best && cpu_has_avx2()) return &nearest_rows_avx2<N>;
#endif
  (void)simd;
  return &nearest_rows_baseline<N>;
}

template <int N>
Scratch<N> make_scratch(const Index<N>& index) {
  Scratch<N> s;
  s.stack.resize(static_cast<std::size_t>(index.depth()) + 1);
  return s;
}

}  // namespace dfvn::nearest_other
