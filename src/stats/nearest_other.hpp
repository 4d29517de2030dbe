// The exact nearest OTHER point of every point of a nanoflann KD-tree (stats/kd_tree.hpp), private to
// stats/: a search specialised for that one question (k = 1 with the point itself excluded, the dimension
// a template parameter, no per-query allocation, no recursion) over a flat copy of nanoflann's tree.
// Rows are queried leaf after leaf; each query first takes its nearest point within its own leaf and
// within the leaf where the previous query found its nearest point (a tight radius before the descent)
// and skips those leaves later; a leaf that the descent reaches is scanned only if its bounding box is
// within the radius. Leaves store their points a block of Lanes at a time (4, or 8 for the AVX-512
// build), coordinate by coordinate, so that one vector instruction takes a coordinate of a whole block.
//
// The answer is the same as nanoflann's k = 2 self-query: the minimum over the other points of the
// squared distance summed over axes in order, each (x - q)^2 rounded as distance_between() rounds it
// (every lane sums its own axes in order; no fused multiply-adds: see CMakeLists.txt), so the distance
// of the row found is the same bits whichever of two tied rows is found, in every build and for every
// leaf size. A subtree or leaf is pruned only when its lower bound exceeds the best squared distance by a
// relative margin (1e-9) far above the bound's rounding (a few units in the last place), so no closer
// point is ever pruned.
//
// Use: nearest_distances<N, kPeriodic>(points, ...) does it all (the Euclidean and the periodic statistics
// call it). Inside: a tree with leaves of up to kLeafSize points; with_kernel<N, kPeriodic>(simd, f) calls
// f(Kernel<N, Lanes>) with the build this CPU runs; in f, an Index<N, Lanes> over the tree and kernel.rows
// called leaf range by leaf range (each thread with its own make_scratch). nearest_of_every_point runs one
// given build (tests, benchmarks).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <vector>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "dfvn/core/point_set.hpp"
#include "dfvn/core/progress.hpp"
#include "dfvn/core/simd.hpp"
#include "dfvn/stats/kd_tree.hpp"
#include "dfvn/stats/neighbour_loop.hpp"

namespace dfvn::nearest_other {

using neighbour_loop::kPruneMargin;

// A leaf's bounding box: N lower coordinates padded with zeros to kBoxLanes, then the N upper ones.
template <int N>
inline constexpr int kBoxLanes = (N + 3) / 4 * 4;

template <int N, int Lanes>
class Index {
 public:
  // 24 bytes. Nodes are stored depth first, so an internal node's first child is the next node.
  struct Node {
    double low = 0.0, high = 0.0;  // internal: child1's points lie at or below low, child2's at or above high
    std::int32_t child2 = -1;      // internal: the second child
    std::int32_t cut = 0;          // internal: the axis cut (>= 0); a leaf: -1 - its index in leaves()
  };
  struct Leaf {
    std::uint32_t first = 0, count = 0;  // rows [first, first + count)
    std::uint32_t block = 0;             // its first block of Lanes points (ceil(count / Lanes) blocks)
    std::uint32_t node = 0;              // its node
  };

  // `tree`: built over `points` (both must outlive the index); its leaves' points are copied in leaf order.
  Index(const PointSet& points, const KdTree<N>& tree) : original_(tree.vAcc.data()) {
    convert(tree.root_node, 1);
    // nanoflann numbers its leaves' points depth first: leaf after leaf, consecutive rows (the callers rely on it).
    for (std::size_t l = 1; l < leaves_.size(); ++l)
      if (leaves_[l].first != leaves_[l - 1].first + leaves_[l - 1].count) throw std::logic_error("KD-tree leaves out of row order");
    std::size_t blocks = 0;
    for (const Leaf& leaf : leaves_) blocks += (leaf.count + Lanes - 1) / Lanes;
    blocks_ = Coordinates(blocks * N * Lanes);  // without zero-fill, on huge pages when large (core/bulk_memory.hpp)
    for (const Leaf& leaf : leaves_)
      for (std::uint32_t j = 0; j < (leaf.count + Lanes - 1) / Lanes * Lanes; ++j) {
        double* block = blocks_.data() + (leaf.block + j / Lanes) * N * Lanes;
        const double* x = j < leaf.count ? points.point(original_[leaf.first + j]) : nullptr;
        for (int k = 0; k < N; ++k)  // padding lanes at +inf: their squared distance is +inf, never a minimum
          block[k * Lanes + j % Lanes] = x ? x[k] : std::numeric_limits<double>::infinity();
      }
    leaf_of_row_.resize(leaves_.empty() ? 0 : leaves_.back().first + leaves_.back().count);
    for (std::size_t l = 0; l < leaves_.size(); ++l)
      std::fill_n(leaf_of_row_.begin() + leaves_[l].first, leaves_[l].count, static_cast<std::uint32_t>(l));
    leaf_boxes_.assign(leaves_.size() * 2 * kBoxLanes<N>, 0.0);
    for (std::size_t l = 0; l < leaves_.size(); ++l) {
      double* box = leaf_boxes_.data() + l * 2 * kBoxLanes<N>;
      for (int k = 0; k < N; ++k) box[k] = std::numeric_limits<double>::infinity(), box[kBoxLanes<N> + k] = -box[k];
      for (std::uint32_t r = leaves_[l].first; r < leaves_[l].first + leaves_[l].count; ++r)
        for (int k = 0; k < N; ++k) {
          const double x = points.point(original_[r])[k];
          box[k] = std::min(box[k], x), box[kBoxLanes<N> + k] = std::max(box[kBoxLanes<N> + k], x);
        }
    }
    // Every subtree's bounding box, children before parents (a child's index is above its parent's).
    std::vector<double> boxes(nodes_.size() * 2 * N);
    extents_.assign(nodes_.size() * 2, 0.0);
    for (std::size_t i = nodes_.size(); i-- > 0;) {
      double* box = boxes.data() + i * 2 * N;
      const Node& nd = nodes_[i];
      if (nd.cut < 0) {
        const double* leaf = leaf_box(static_cast<std::size_t>(-1 - nd.cut));
        for (int k = 0; k < N; ++k) box[k] = leaf[k], box[N + k] = leaf[kBoxLanes<N> + k];
        continue;
      }
      const double* a = boxes.data() + (i + 1) * 2 * N;
      const double* b = boxes.data() + static_cast<std::size_t>(nd.child2) * 2 * N;
      for (int k = 0; k < N; ++k) box[k] = std::min(a[k], b[k]), box[N + k] = std::max(a[N + k], b[N + k]);
      extents_[2 * i] = a[nd.cut], extents_[2 * i + 1] = b[N + nd.cut];
    }
  }
  Index(const Index&) = delete;
  Index& operator=(const Index&) = delete;

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<Leaf>& leaves() const { return leaves_; }
  // Row r (the rows are the leaves' points, leaf after leaf) is input point original()[r].
  const std::uint32_t* original() const { return original_; }
  const double* blocks() const { return blocks_.data(); }
  const double* leaf_box(std::size_t l) const { return leaf_boxes_.data() + l * 2 * kBoxLanes<N>; }
  // Internal node i's first child's lowest and second child's highest coordinate on its cut axis: where the
  // way round the torus to each child ends (the periodic search).
  const double* extents() const { return extents_.data(); }
  const std::uint32_t* leaf_of_row() const { return leaf_of_row_.data(); }
  int depth() const { return depth_; }

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
      leaf.block = leaves_.empty() ? 0 : leaves_.back().block + (leaves_.back().count + Lanes - 1) / Lanes;
      leaf.node = self;
      nodes_[self].cut = -1 - static_cast<std::int32_t>(leaves_.size());
      leaves_.push_back(leaf);
      return self;
    }
    nodes_[self].cut = node->node_type.sub.divfeat;
    nodes_[self].low = node->node_type.sub.divlow;
    nodes_[self].high = node->node_type.sub.divhigh;
    convert(node->child1, depth + 1);  // node self + 1
    nodes_[self].child2 = static_cast<std::int32_t>(convert(node->child2, depth + 1));
    return self;
  }

  const std::uint32_t* original_;
  std::vector<Node> nodes_;
  std::vector<Leaf> leaves_;
  Coordinates blocks_;
  std::vector<double> leaf_boxes_;
  std::vector<double> extents_;
  std::vector<std::uint32_t> leaf_of_row_;
  int depth_ = 0;
};

// GCC's generic vectors of four doubles: two SSE2 instructions each in the baseline build, one AVX
// instruction each in the AVX2 and AVX-512 builds that this code is inlined into.
typedef double Vec4 __attribute__((vector_size(4 * sizeof(double))));

// The torus [lo, lo + side)^N of the periodic search; slack: how much shorter than computed each way
// round through a face is taken to be (far more than that way's rounding; stats/periodic_neighbours.cpp).
struct Torus {
  double lo = 0.0, side = 0.0, slack = 0.0;
};

// The torus [lo, lo + side)^N with its slack: the ways round are computed from lo, lo + side and the
// coordinates, to a few units in the last place of the largest of them; 2^-40 of their size is far more
// (and far below any spacing that matters).
inline Torus periodic_torus(double lo, double side) {
  return Torus{lo, side, (std::abs(lo) + std::abs(lo + side) + side) * 0x1p-40};
}

// The squared distance from point q (kBoxLanes coordinates, zero-padded) to the box `box` (Index::leaf_box),
// summed in no particular order. kPeriodic: on `torus`, each axis's gap the shorter of the way straight to
// the box and the way round through the opposite face (less torus.slack).
template <int N, bool kPeriodic = false>
[[gnu::always_inline]] inline double box_distance(const double* q, const double* box, const Torus& torus = {}) {
  constexpr int kBox = kBoxLanes<N>;
  Vec4 sum = {};
  for (int v = 0; v < kBox; v += 4) {
    Vec4 lo, hi, qv;
    std::memcpy(&lo, box + v, sizeof lo);
    std::memcpy(&hi, box + kBox + v, sizeof hi);
    std::memcpy(&qv, q + v, sizeof qv);
    const Vec4 below = lo - qv, above = qv - hi;
    Vec4 gap = below > above ? below : above;
    if constexpr (kPeriodic) {
      // q below the box: round through the lower face to the box's top; above it: through the upper face.
      const Vec4 round_below = (torus.side - (hi - qv)) - torus.slack, round_above = (torus.side - (qv - lo)) - torus.slack;
      const Vec4 round = below > above ? round_below : round_above;
      gap = round < gap ? round : gap;
    }
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

// Scratch for one thread: the subtrees left for later (each node on a path leaves at most one, and the
// descent writes one more entry above the top).
template <int N>
struct Scratch {
  std::vector<StackEntry<N>> stack;
};

template <int N, int Lanes>
Scratch<N> make_scratch(const Index<N, Lanes>& index) {
  Scratch<N> s;
  s.stack.resize(static_cast<std::size_t>(index.depth()) + 1);
  return s;
}

// The three builds of the search (stats/nearest_other_kernel.inc), each in its own namespace.
namespace baseline {
inline constexpr int kLanes = 4;
using Lanes = Vec4;
[[gnu::always_inline]] inline unsigned lanes_below(const Lanes& acc, double best) {
  return static_cast<unsigned>(acc[0] < best) | static_cast<unsigned>(acc[1] < best) << 1 |
         static_cast<unsigned>(acc[2] < best) << 2 | static_cast<unsigned>(acc[3] < best) << 3;
}
#include "dfvn/stats/nearest_other_kernel.inc"
}  // namespace baseline

#if defined(__x86_64__)
#pragma GCC push_options
#pragma GCC target("avx2")
namespace avx2 {
inline constexpr int kLanes = 4;
using Lanes = Vec4;
inline unsigned lanes_below(const Lanes& acc, double best) {
  return static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(__m256d(acc), _mm256_set1_pd(best), _CMP_LT_OQ)));
}
#include "dfvn/stats/nearest_other_kernel.inc"
}  // namespace avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f,avx512dq,avx512vl")
namespace avx512 {
inline constexpr int kLanes = 8;
typedef double Lanes __attribute__((vector_size(8 * sizeof(double))));
inline unsigned lanes_below(const Lanes& acc, double best) {
  return _mm512_cmp_pd_mask(__m512d(acc), _mm512_set1_pd(best), _CMP_LT_OQ);
}
#include "dfvn/stats/nearest_other_kernel.inc"
}  // namespace avx512
#pragma GCC pop_options
#endif

template <int N, int Lanes>
using NearestRows = void (*)(const Index<N, Lanes>&, std::size_t, std::size_t, std::uint32_t, std::uint32_t*, Scratch<N>&,
                             const Torus&);

// Leaves of up to 64 points (nanoflann's default is 10, kept by the other trees of stats/): with a block
// of points to a vector instruction a leaf costs little more to scan than a node to pass, and fewer,
// larger leaves mean fewer nodes per query. On the CNJ, Sobol and Poisson disk sets of the main job's
// kind in 2D-8D (bench/nearest_leaf_sizes, bench/results.md), 64 took at most 1.12x the time of the
// fastest of 16-128 in every dimension and build, and less than 32 in most.
inline constexpr int kLeafSize = 64;

// A build of the search.
template <int N, int Lanes>
struct Kernel {
  NearestRows<N, Lanes> rows;
};

// Calls f(Kernel<N, Lanes>) with the widest build this CPU runs (`simd` best) or the baseline build
// (core/simd.hpp); every build finds rows at the same distances, bit for bit. kPeriodic: the search on a
// torus (its rows take the Torus; the Euclidean search ignores it).
template <int N, bool kPeriodic = false, class F>
decltype(auto) with_kernel(Simd simd, F&& f) {
#if defined(__x86_64__)
  if (simd == Simd::best && cpu_has_avx512()) return f(Kernel<N, 8>{&avx512::nearest_rows<N, kPeriodic>});
  if (simd == Simd::best && cpu_has_avx2()) return f(Kernel<N, 4>{&avx2::nearest_rows<N, kPeriodic>});
#endif
  return f(Kernel<N, 4>{&baseline::nearest_rows<N, kPeriodic>});
}

// Calls f(lanes, rows_within) with the widest build this CPU runs (`simd` best) or the baseline build:
// lanes a std::integral_constant<int, Lanes>, rows_within(index, q, search2, scratch, visit) that build's
// rows_within over an Index<N, Lanes> (stats/nearest_other_kernel.inc). Every build visits the same rows
// at the same squared distances, bit for bit.
template <int N, class F>
decltype(auto) with_rows_within(Simd simd, F&& f) {
#if defined(__x86_64__)
  if (simd == Simd::best && cpu_has_avx512())
    return f(std::integral_constant<int, 8>{}, [](const Index<N, 8>& index, const double* q, double search2, Scratch<N>& s,
                                                  auto&& visit) { avx512::rows_within<N>(index, q, search2, s, visit); });
  if (simd == Simd::best && cpu_has_avx2())
    return f(std::integral_constant<int, 4>{}, [](const Index<N, 4>& index, const double* q, double search2, Scratch<N>& s,
                                                  auto&& visit) { avx2::rows_within<N>(index, q, search2, s, visit); });
#endif
  return f(std::integral_constant<int, 4>{}, [](const Index<N, 4>& index, const double* q, double search2, Scratch<N>& s,
                                                auto&& visit) { baseline::rows_within<N>(index, q, search2, s, visit); });
}

// distances[i] = distance(i, j) for each of the first `queries` points i and a nearest other point j (on
// `torus` if kPeriodic: `distance` then measures on it), with the widest build this CPU runs, in parallel
// over chunks of leaves (the same result for any thread count); progress counts leaves done.
template <int N, bool kPeriodic, class Distance>
std::vector<double> nearest_distances(const PointSet& points, std::size_t queries, int threads, const FractionProgress& progress,
                                      const Torus& torus, const Distance& distance) {
  if (points.size() > std::numeric_limits<std::uint32_t>::max())  // the tree's rows are 32-bit
    throw std::invalid_argument("the nearest-neighbour search takes at most 2^32 - 1 points");
  const PointSetAdaptor<N> adaptor{points};
  const KdTree<N> tree(N, adaptor, kd_tree_params(kLeafSize));  // built by its constructor
  std::vector<double> distances(queries);
  with_kernel<N, kPeriodic>(Simd::best, [&]<int Lanes>(Kernel<N, Lanes> kernel) {
    const Index<N, Lanes> index(points, tree);
    const std::uint32_t* original = index.original();
    const auto& leaves = index.leaves();
    const auto limit = static_cast<std::uint32_t>(queries);
    neighbour_loop::for_every_chunk(leaves.size(), threads, progress, [&](std::size_t begin, std::size_t end) {
      Scratch<N> scratch = make_scratch(index);
      const std::size_t first = leaves[begin].first, last = leaves[end - 1].first + leaves[end - 1].count;
      std::vector<std::uint32_t> nearest(last - first);
      kernel.rows(index, begin, end, limit, nearest.data(), scratch, torus);
      for (std::size_t r = first; r < last; ++r)
        if (original[r] < limit) distances[original[r]] = distance(original[r], original[nearest[r - first]]);
    });
  });
  return distances;
}

// For tests and benchmarks: the input index of a nearest other point of every point, found by the one build
// `rows` over a tree with leaves of up to `leaf` points, on one thread.
template <int N, int Lanes>
std::vector<std::uint32_t> nearest_of_every_point(const PointSet& points, NearestRows<N, Lanes> rows, int leaf,
                                                  const Torus& torus = {}) {
  const PointSetAdaptor<N> adaptor{points};
  const KdTree<N> tree(N, adaptor, kd_tree_params(leaf));
  const Index<N, Lanes> index(points, tree);
  std::vector<std::uint32_t> nearest(points.size()), result(points.size());
  Scratch<N> scratch = make_scratch(index);
  rows(index, 0, index.leaves().size(), static_cast<std::uint32_t>(points.size()), nearest.data(), scratch, torus);
  for (std::size_t r = 0; r < points.size(); ++r) result[index.original()[r]] = index.original()[nearest[r]];
  return result;
}

}  // namespace dfvn::nearest_other
