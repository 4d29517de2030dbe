#include "dfvn/stats/cell_grid_neighbours.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "dfvn/core/dimension.hpp"
#include "dfvn/core/simd.hpp"
#include "dfvn/stats/neighbour_loop.hpp"

namespace dfvn::cell_grid {


namespace {

// The largest count of points in one cell the grid accepts: with about one point per cell, uniform random
// sets of 10^4-10^7 points reach 8-11.
constexpr std::uint32_t kMostInACell = 32;
// The fewest axes the grid takes. In 2D and 3D a line of cells holds n^(1/N) points, far more than a search
// needs, and on a million uniform random points the KD-tree search took 0.4x and 0.9x the grid's time. In
// 4D-7D the grid took 0.55x, 0.48x, 0.43x and 0.41x the tree's on a million, 0.52x, 0.39x and 0.38x on the
// 7D main job's CNJ, Sobol and Poisson disk sets, and 0.45x on 400,000 in 8D (bench/periodic_grid_vs_tree,
// bench/results.md).
constexpr int kFewestAxes = 4;
using neighbour_loop::kPruneMargin;  // the KD-tree search's relative pruning margin

// The grid: m cells per axis, of side h from lo (the torus is a cube). A line is the m cells along the last axis; its points
// are consecutive rows [begin[l], end[l]) in blocks of 8 rows (begin[l] a multiple of 8, the rows after
// end[l] up to the next block padding at +inf), a block holding coordinate k of its rows at 8 k + lane.
template <int N>
struct Grid {
  int m = 0;
  double lo = 0.0, h = 0.0, slack = 0.0, side = 0.0, half_side = 0.0;
  std::vector<std::uint32_t> begin, end;  // per line
  std::vector<double> blocks;             // 8 N doubles a block of 8 rows
  std::vector<std::uint32_t> original;    // row r is input point original[r] (padding: none)
  std::vector<std::uint32_t> cell;        // row r's cell
  std::size_t rows = 0;                   // rows, padding included
};

typedef double V8 __attribute__((vector_size(8 * sizeof(double))));

// The three builds of the search (stats/cell_grid_kernel.inc), each in its own namespace.
namespace baseline {
inline unsigned lanes_below(const V8& acc, double best) {
  unsigned bits = 0;
  for (int lane = 0; lane < 8; ++lane) bits |= static_cast<unsigned>(acc[lane] < best) << lane;
  return bits;
}
#include "dfvn/stats/cell_grid_kernel.inc"
}  // namespace baseline

#if defined(__x86_64__)
#pragma GCC push_options
#pragma GCC target("avx2")
namespace avx2 {
using baseline::lanes_below;  // its loop, inlined here in AVX2 instructions
#include "dfvn/stats/cell_grid_kernel.inc"
}  // namespace avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f,avx512dq,avx512vl")
namespace avx512 {
inline unsigned lanes_below(const V8& acc, double best) {
  return _mm512_cmp_pd_mask(__m512d(acc), _mm512_set1_pd(best), _CMP_LT_OQ);
}
#include "dfvn/stats/cell_grid_kernel.inc"
}  // namespace avx512
#pragma GCC pop_options
#endif

template <int N>
using NearestRows = void (*)(const Grid<N>&, std::size_t, std::size_t, std::size_t, double*);

// The widest build this CPU runs; every build finds rows at the same distances, bit for bit.
template <int N>
NearestRows<N> widest_build(Simd simd) {
#if defined(__x86_64__)
  if (simd == Simd::best && cpu_has_avx512()) return &avx512::nearest_rows<N>;
  if (simd == Simd::best && cpu_has_avx2()) return &avx2::nearest_rows<N>;
#endif
  return &baseline::nearest_rows<N>;
}

template <int N>
std::optional<std::vector<double>> search(const PointSet& points, std::size_t queries, int threads,
                                          const FractionProgress& progress, Simd simd) {
  const std::size_t n = points.size();
  if (n >= std::numeric_limits<std::uint32_t>::max() / 2) return std::nullopt;
  Grid<N> g;
  // About one point per cell: m = floor(n^(1/N)), corrected for the rounding of pow.
  const auto cells_of = [](int per_axis) {
    double c = 1.0;
    for (int k = 0; k < N; ++k) c *= per_axis;
    return c;
  };
  int m = static_cast<int>(std::floor(std::pow(static_cast<double>(n), 1.0 / N)));
  while (cells_of(m + 1) <= static_cast<double>(n)) ++m;
  while (m > 1 && cells_of(m) > static_cast<double>(n)) --m;
  if (m < 4) return std::nullopt;
  g.m = m;
  g.side = points.domain.side, g.half_side = 0.5 * g.side;
  g.lo = points.domain.lo, g.h = g.side / m;
  // A point may sit a rounding outside the cell its coordinates put it in: the faces are taken this much
  // nearer (far above that rounding, far below any spacing that matters).
  g.slack = (std::abs(g.lo) + g.side) * 0x1p-40;
  const auto cells = static_cast<std::size_t>(cells_of(m));
  const std::size_t lines = cells / static_cast<std::size_t>(m);
  // Each point's cell (the last cell holds the upper face), then the rows sorted by cell, stably, each line
  // padded to whole blocks.
  std::vector<std::uint32_t> cell_of_point(n), in_cell(cells + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t c = 0;
    for (int k = 0; k < N; ++k) {
      const double u = (points.point(i)[k] - g.lo) / g.h;
      const int ck = std::clamp(static_cast<int>(u), 0, m - 1);
      c = c * static_cast<std::uint32_t>(m) + static_cast<std::uint32_t>(ck);
    }
    cell_of_point[i] = c;
    if (++in_cell[c + 1] > kMostInACell) return std::nullopt;
  }
  g.begin.resize(lines), g.end.resize(lines);
  std::vector<std::uint32_t> fill(cells);  // the next row of each cell
  std::size_t row = 0;
  for (std::size_t l = 0; l < lines; ++l) {
    g.begin[l] = static_cast<std::uint32_t>(row);
    for (std::size_t c = l * m; c < (l + 1) * m; ++c) fill[c] = static_cast<std::uint32_t>(row), row += in_cell[c + 1];
    g.end[l] = static_cast<std::uint32_t>(row);
    row = (row + 7) / 8 * 8;
    if (row >= std::numeric_limits<std::uint32_t>::max()) return std::nullopt;
  }
  g.rows = row;
  g.blocks.assign(g.rows * N, std::numeric_limits<double>::infinity());
  g.original.assign(g.rows, std::numeric_limits<std::uint32_t>::max());
  g.cell.assign(g.rows, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t r = fill[cell_of_point[i]]++;
    g.original[r] = static_cast<std::uint32_t>(i);
    g.cell[r] = cell_of_point[i];
    for (int k = 0; k < N; ++k) g.blocks[(r / 8) * 8 * N + k * 8 + r % 8] = points.point(i)[k];
  }
  const NearestRows<N> rows = widest_build<N>(simd);
  std::vector<double> nearest2(g.rows);
  neighbour_loop::for_every_chunk(lines, threads, progress, [&](std::size_t begin, std::size_t end) {
    rows(g, begin, end, queries, nearest2.data());
  });
  // The square root of the smallest squared distance, summed as periodic_distance_between() sums it: the
  // distance it gives for that pair, bit for bit.
  std::vector<double> distances(queries);
  for (std::size_t r = 0; r < g.rows; ++r)
    if (g.original[r] < queries) distances[g.original[r]] = std::sqrt(nearest2[r]);
  return distances;
}

}  // namespace

std::optional<std::vector<double>> periodic_nearest_distances(const PointSet& points, std::size_t queries, int threads,
                                                              const FractionProgress& progress, Simd simd) {
  if (points.size() < 2 || queries == 0 || points.dimension < kFewestAxes) return std::nullopt;
  return dispatch_dimension(points.dimension, [&]<int N>() { return search<N>(points, queries, threads, progress, simd); });
}

}  // namespace dfvn::cell_grid
