#include "dfvn/sampling/poisson_disk.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <exception>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "dfvn/core/bulk_memory.hpp"
#include "dfvn/core/dimension.hpp"
#include "dfvn/core/hash.hpp"
#include "dfvn/core/parallel.hpp"
#include "dfvn/sampling/annulus.hpp"

namespace dfvn {

void PoissonDiskOptions::validate(int dimension) const {
  if (!std::isfinite(radius) || radius <= 0.0) throw std::invalid_argument("PDS radius must be a finite number > 0");
  if (candidates < 1) throw std::invalid_argument("PDS candidates must be at least 1");
  if (!std::isfinite(domain.lo) || !std::isfinite(domain.side) || domain.side <= 0.0)
    throw std::invalid_argument("PDS domain must be a finite box with positive side");
  if (domain.kind == DomainKind::sphere) throw std::invalid_argument("PDS samples a torus, a cube or a ball, not the sphere");
  // On the torus a point must not meet its own image, and each pair has one nearest image.
  if (domain.periodic() && !(radius < 0.5 * domain.side))
    throw std::invalid_argument("PDS radius " + std::to_string(radius) + " on the torus must be below half its side (" +
                                std::to_string(domain.side) + ")");
  const double cells = std::ceil(domain.side / radius);
  const double max_cells = std::ldexp(1.0, 64 / dimension) - 1.0;
  if (cells > max_cells)
    throw std::invalid_argument("PDS radius " + std::to_string(radius) + " is too small for a domain of side " +
                                std::to_string(domain.side) + " in " + std::to_string(dimension) +
                                "D (at most " + std::to_string(static_cast<long long>(max_cells)) +
                                " cells of side r per axis)");
}

namespace {

// ---------------------------------------------------------------------------------------------------
// Memory that other threads may read while one thread appends.

// A zero-filled array of trivial T on anonymous pages, which the kernel zeroes when first touched
// (no fill pass, and untouched pages cost nothing), on transparent huge pages where the system
// offers them: the grid's accesses are scattered over tens of MB, and on 4 KB pages nearly every one
// would also miss the TLB.
template <class T>
class ZeroedPages {
 public:
  ZeroedPages() = default;
  explicit ZeroedPages(std::size_t count) : bytes_(std::max<std::size_t>(count, 1) * sizeof(T)) {
    data_ = static_cast<T*>(map_pages(bytes_));
  }
  ZeroedPages(const ZeroedPages&) = delete;
  ZeroedPages& operator=(ZeroedPages&& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(bytes_, other.bytes_);
    return *this;
  }
  ~ZeroedPages() {
    release_pages(data_, bytes_);
  }
  T* data() const { return data_; }

 private:
  T* data_ = nullptr;
  std::size_t bytes_ = 0;
};

// Append-only items whose addresses never change: chunks of 2^16 behind a fixed directory. One thread
// writes; other threads read the items it published to them (with a release store of a count that
// they load with acquire), so no item is read while it is written.
template <class T>
class StableArray {
 public:
  StableArray() : directory_(kChunks) {}
  StableArray(const StableArray&) = delete;
  StableArray& operator=(const StableArray&) = delete;
  ~StableArray() {
    for (std::size_t c = 0; c < kChunks && directory_.data()[c]; ++c) delete[] directory_.data()[c];
  }
  const T& operator[](std::size_t i) const {
    return std::atomic_ref<T*>(directory_.data()[i >> kChunkBits]).load(std::memory_order_acquire)[i & (kChunk - 1)];
  }
  // The writer's slot for item i; items are written in order, so chunks are allocated in order.
  T& slot(std::size_t i) {
    const std::size_t c = i >> kChunkBits;
    if (c >= kChunks) throw std::length_error("Poisson disk sampling holds at most 2^32 points and queue entries");
    T* chunk = directory_.data()[c];
    if (!chunk) {
      chunk = new T[kChunk];
      std::atomic_ref<T*>(directory_.data()[c]).store(chunk, std::memory_order_release);
    }
    return chunk[i & (kChunk - 1)];
  }

 private:
  static constexpr std::size_t kChunkBits = 16, kChunk = std::size_t{1} << kChunkBits, kChunks = std::size_t{1} << 16;
  ZeroedPages<T*> directory_;
};

template <class T>
T load_acquire(const T& v) {
  return std::atomic_ref<T>(const_cast<T&>(v)).load(std::memory_order_acquire);
}
template <class T>
void store_release(T& v, T value) {
  std::atomic_ref<T>(v).store(value, std::memory_order_release);
}

// ---------------------------------------------------------------------------------------------------
// The grid of cells of side r.

// A cell holds its first kSlots points inline, with its count (coordinates in cell order: a record of
// one to three cache lines), further ones in a shared overflow list. Saturated sets hold about 0.7
// points per cell in 2D-5D, about 1 in 7D and 1.4 in 8D; with these slots about 1% of the points
// (5% in 7D-8D) overflow, against 30% in 7D with one slot.
template <int N>
inline constexpr int kSlots = N == 2 ? 3 : N == 3 ? 2 : N <= 5 ? 3 : 2;

template <int N>
struct alignas(64) CellRecord {
  std::uint32_t count;     // points in the cell; written with release after their coordinates
  std::uint32_t overflow;  // 1-based head of the cell's overflow list (0: none), written with release
  double x[kSlots<N>][N];
};

template <int N>
struct OverflowPoint {
  double x[N];
  std::uint32_t next;  // 1-based; 0 ends the list
};

// Cells of side r: a point can conflict only with points in the cells whose box comes closer than r
// (offsets -1, 0, +1 per axis; about 550 cells in 7D, of 2187), and every point there is compared by
// its exact distance, so no conflict is ever missed. Dense: all (side / r)^N cells in one array, id =
// linear index; hashed: the occupied cells, ids in order of first use, in a table of fixed capacity.
// One thread inserts; any thread may call conflicts() meanwhile.
template <int N>
class CellGrid {
 public:
  struct Query {
    const double* x;
    std::uint64_t base;  // key of x's cell
    std::int64_t cell[N];
    double below2[N], above2[N];
  };

  CellGrid(const Domain& domain, double radius, bool dense, std::uint64_t max_points)
      : lo_(domain.lo), cell_(radius), r2_(radius * radius), dense_(dense), periodic_(domain.periodic()),
        side_(domain.side) {
    const bool safe = r2_ >= 1e-250 && r2_ <= 1e250 && side_ * side_ <= 1e250;
    below_r2_ = safe ? r2_ * (1.0 - 1e-12) : -std::numeric_limits<double>::infinity();
    above_r2_ = safe ? r2_ * (1.0 + 1e-12) : std::numeric_limits<double>::infinity();
    cells_per_axis_ = static_cast<std::int64_t>(std::max(1.0, std::ceil(domain.side / radius)));
    if (periodic_) {
      // The torus: whole cells that tile it, of side side / floor(side / r) >= r, so that the neighbours
      // -1, 0, +1 across the identified faces still hold every point within r (r < side / 2: at least 2).
      cells_per_axis_ = static_cast<std::int64_t>(std::floor(domain.side / radius));
      cell_ = domain.side / static_cast<double>(cells_per_axis_);
    }
    std::uint64_t capacity = 0;  // cell records
    if (dense_) {
      std::uint64_t stride = 1;
      for (int j = N - 1; j >= 0; --j) {
        stride_[j] = stride;
        stride *= static_cast<std::uint64_t>(cells_per_axis_);
      }
      capacity = stride;
    } else {
      int bits = 1;
      while ((std::int64_t{1} << bits) - 1 < cells_per_axis_) ++bits;
      for (int j = 0; j < N; ++j) stride_[j] = std::uint64_t{1} << (bits * (N - 1 - j));
      // Each point occupies at most one new cell; the table stays at most half full.
      capacity = static_cast<std::uint64_t>(
          std::min(static_cast<double>(max_points), std::pow(static_cast<double>(cells_per_axis_), N)));
      std::size_t slots = 1024;
      while (slots < 2 * capacity) slots *= 2;
      keys_ = ZeroedPages<std::uint64_t>(slots);
      ids_ = ZeroedPages<std::uint32_t>(slots);
      slot_mask_ = slots - 1;
    }
    records_ = ZeroedPages<CellRecord<N>>(capacity);
    occupied_ = ZeroedPages<std::uint64_t>((capacity + 63) / 64);
    last_point_ = ZeroedPages<std::uint32_t>(capacity);
  }

  // True if a stored point is closer than r to x. Any thread: it sees every point inserted before it
  // acquired the inserting thread's count, and perhaps later ones, each whole. Two passes: first the
  // cells within r/2 (where a conflict, if any, is usually found, in a few cells), then the others.
  // Non-empty cells are checked a few behind the ones found, which are prefetched, so that several
  // cache misses overlap and the search still stops at the first conflict.
  bool conflicts(const Query& q) const {
    const double* x = q.x;
    Lookahead look(*this, x);
    if (near_cells(q, [&](std::uint64_t key) { return look.push(id_of(key)); }) || look.drain()) return true;
    // A cell of the first pass has bound < r^2/4 there, summed in another order: equal to within a
    // few ulps, so skipping bounds below r^2/4 (1 - 1e-9) here never skips a cell it left out.
    const double seen2 = kFirstPass * r2_ * (1.0 - 1e-9);
    // The second pass lists its non-empty cells first, without a branch per cell (a third of them
    // hold a point), then checks them with the records a few ahead prefetched.
    std::size_t ids[pow3(N)];
    std::size_t count = 0;
    for_each_cell(q, [&](std::uint64_t key, double bound2) {
      const std::size_t id = id_of(key);
      const bool known = id != kNoCell;
      ids[count] = id;
      count += (bound2 >= seen2) & known & occupied(known ? id : 0);
      return false;
    });
    for (std::size_t i = 0; i < std::min(count, kLookahead); ++i) prefetch_record(ids[i]);
    for (std::size_t i = 0; i < count; ++i) {
      if (i + kLookahead < count) prefetch_record(ids[i + kLookahead]);
      if (cell_conflicts(records_.data()[ids[i]], x)) return true;
    }
    return false;
  }

  // x's query for conflicts(), made a candidate ahead: it starts fetching the record of x's own cell,
  // the first that conflicts() reads, while the caller checks the candidate before (hashed: no fetch).
  // Fetching the nearer-face neighbours' records too was slower (7D: 4.9 s -> 5.7 s).
  Query prepare(const double* x) const {
    const Query q = query(x);
    if (!dense_) return q;
    __builtin_prefetch(&records_.data()[q.base]);
    return q;
  }

  // Inserting thread: true if a point with index >= since is closer than r to x.
  bool conflicts_since(const double* x, std::uint32_t since) const {
    const Query q = query(x);
    return for_each_cell(q, [&](std::uint64_t key, double) {
      const std::size_t id = id_of(key);
      return id != kNoCell && last_point_.data()[id] > since && cell_conflicts(records_.data()[id], x);
    });
  }

  // Inserting thread only. `index`: the point's index in the output.
  void insert(const double* x, std::uint32_t index) {
    std::uint64_t key = 0;
    for (int j = 0; j < N; ++j) key += static_cast<std::uint64_t>(cell_of(x[j])) * stride_[j];
    const std::size_t id = dense_ ? key : id_or_add(key);
    CellRecord<N>& cell = records_.data()[id];
    if (cell.count < kSlots<N>) {
      std::copy(x, x + N, cell.x[cell.count]);
    } else {
      const std::size_t o = overflow_count_++;
      OverflowPoint<N>& p = overflow_.slot(o);
      std::copy(x, x + N, p.x);
      p.next = cell.overflow;
      store_release(cell.overflow, static_cast<std::uint32_t>(o + 1));
    }
    store_release(cell.count, cell.count + 1);
    std::atomic_ref<std::uint64_t>(occupied_.data()[id / 64]).fetch_or(std::uint64_t{1} << (id % 64), std::memory_order_release);
    last_point_.data()[id] = index + 1;
  }

 private:
  static constexpr std::size_t kNoCell = ~std::size_t{0};
  static constexpr double kFirstPass = 0.25;  // the first pass: cells within r/2 (r^2/4)
  static constexpr std::size_t kLookahead = 8;      // cells prefetched ahead of the one checked

  void prefetch_record(std::size_t id) const {
    const auto* record = reinterpret_cast<const char*>(&records_.data()[id]);
    for (std::size_t line = 0; line < sizeof(CellRecord<N>); line += 64) __builtin_prefetch(record + line);
  }

  Query query(const double* x) const {
    Query q;
    q.x = x;
    q.base = 0;
    for (int j = 0; j < N; ++j) {
      q.cell[j] = cell_of(x[j]);
      q.base += static_cast<std::uint64_t>(q.cell[j]) * stride_[j];
      // Distances to the lower and upper faces of x's cell, shrunk by a hair so that rounding in
      // cell_of() or in the sums of squares can never prune a cell that holds a conflicting point.
      const double offset = x[j] - (lo_ + static_cast<double>(q.cell[j]) * cell_);
      q.below2[j] = square(std::max(0.0, offset - 1e-12 * cell_));
      q.above2[j] = square(std::max(0.0, cell_ - offset - 1e-12 * cell_));
    }
    return q;
  }

  static double square(double v) { return v * v; }

  std::int64_t cell_of(double v) const {
    // Truncation, not floor: they differ only below 0, which the clamp takes to 0 either way.
    const auto c = static_cast<std::int64_t>((v - lo_) / cell_);
    return std::clamp<std::int64_t>(c, 0, cells_per_axis_ - 1);
  }

  bool occupied(std::size_t id) const {
    return (std::atomic_ref<std::uint64_t>(occupied_.data()[id / 64]).load(std::memory_order_relaxed) >> (id % 64)) & 1;
  }

  // Non-empty cells found, prefetched, and checked a few behind.
  struct Lookahead {
    Lookahead(const CellGrid& g, const double* point) : grid(g), x(point) {}
    const CellGrid& grid;
    const double* x;
    std::size_t ring[kLookahead];
    std::size_t found = 0, checked = 0;

    bool push(std::size_t id) {
      if (id == kNoCell || !grid.occupied(id)) return false;
      const auto* record = reinterpret_cast<const char*>(&grid.records_.data()[id]);
      for (std::size_t line = 0; line < sizeof(CellRecord<N>); line += 64) __builtin_prefetch(record + line);
      ring[found++ % kLookahead] = id;
      // Checked at once while few cells were checked (the first non-empty cell, mostly x's own, holds
      // the conflict in 40-60% of queries), then up to kLookahead - 1 behind.
      return found - checked > std::min(checked, kLookahead - 1) &&
             grid.cell_conflicts(grid.records_.data()[ring[checked++ % kLookahead]], x);
    }
    bool drain() {
      for (; checked < found; ++checked)
        if (grid.cell_conflicts(grid.records_.data()[ring[checked % kLookahead]], x)) return true;
      return false;
    }
  };

  // The cells whose box comes closer than r/2 to x. The farther face of x's cell is at least r/2 away
  // on every axis, so these cells are x's own and its neighbours towards the nearer faces on a subset
  // of axes whose squared distances sum below r^2/4. They are listed by adding one axis at a time,
  // nearest first, to the subsets found so far (a subset below the limit has all its own subsets below
  // it, summed in the same order), and each is checked as it is found: x's own cell, the nearest
  // neighbour, the next, both, ..., about in increasing distance, so that the conflict, if any, is
  // found in fewer cells (4.4 checked per 7D query, against 7.3 depth first) and the farther axes are
  // mostly never reached.
  template <class Leaf>
  bool near_cells(const Query& q, const Leaf& leaf) const {
    // The axes by distance of the nearer face (a stable sort, by counting, without a branch to
    // mispredict); axes at the grid's edge on the near side have no cell there: last, at infinity.
    double d2[N];
    std::int64_t offset[N];
    int axes = 0;
    for (int j = 0; j < N; ++j) {
      const bool down = q.below2[j] <= q.above2[j];
      const bool none = !periodic_ && (down ? q.cell[j] == 0 : q.cell[j] + 1 == cells_per_axis_);
      d2[j] = none ? std::numeric_limits<double>::infinity() : down ? q.below2[j] : q.above2[j];
      offset[j] = static_cast<std::int64_t>(down ? step_down(q, j) : step_up(q, j));
      axes += none ? 0 : 1;
    }
    double near2[N];
    std::int64_t step[N];
    for (int j = 0; j < N; ++j) {
      int rank = 0;
      for (int k = 0; k < N; ++k) rank += (d2[k] < d2[j]) | ((k < j) & (d2[k] == d2[j]));
      near2[rank] = d2[j];
      step[rank] = offset[j];
    }
    const double limit2 = kFirstPass * r2_;
    constexpr std::size_t kAll = std::size_t{1} << N;
    double sum[kAll];
    std::uint64_t key[kAll];
    sum[0] = 0.0;
    key[0] = q.base;
    if (leaf(q.base)) return true;
    std::size_t count = 1;
    for (int i = 0; i < axes && near2[i] < limit2; ++i) {
      const std::size_t before = count;
      const std::uint64_t s = static_cast<std::uint64_t>(step[i]);
      for (std::size_t m = 0; m < before; ++m) {
        const double t = sum[m] + near2[i];
        if (t < limit2) {
          sum[count] = t;
          key[count] = key[m] + s;
          if (leaf(key[count++])) return true;
        }
      }
    }
    return false;
  }

  // Every cell whose box comes closer than r to x, meeting in the middle: the offset combinations of
  // the first kFirstAxes axes and of the others are listed with their squared distances (pruned at
  // r^2), the second list sorted, and each first-half combination is paired with the prefix of the
  // second list that keeps the sum below r^2: a flat double loop, about twice as fast as a depth-first
  // search over the axes.
  static constexpr int kLastAxes = N >= 6 ? 3 : N / 2;
  static constexpr int kFirstAxes = N - kLastAxes;
  static constexpr int pow3(int k) { return k == 0 ? 1 : 3 * pow3(k - 1); }
  struct Part {
    double bound2;
    std::uint64_t key;  // offset from x's cell
  };

  template <int First, int Last>
  int parts(const Query& q, Part* out) const {
    int count = 1;
    out[0] = {0.0, 0};
    for (int j = First; j < Last; ++j) {
      const int before = count;
      const bool can_down = periodic_ || q.cell[j] > 0, can_up = periodic_ || q.cell[j] + 1 < cells_per_axis_;
      const std::uint64_t down_step = step_down(q, j), up_step = step_up(q, j);
      for (int i = 0; i < before; ++i) {
        const Part p = out[i];
        const double down = p.bound2 + q.below2[j], up = p.bound2 + q.above2[j];
        if (can_down && down < r2_) out[count++] = {down, p.key + down_step};
        if (can_up && up < r2_) out[count++] = {up, p.key + up_step};
      }
    }
    return count;
  }

  template <class Leaf>
  bool for_each_cell(const Query& q, const Leaf& leaf) const {
    Part first[pow3(kFirstAxes)], last[pow3(kLastAxes)];
    const int first_count = parts<0, kFirstAxes>(q, first), last_count = parts<kFirstAxes, N>(q, last);
    for (int i = 1; i < last_count; ++i)  // insertion sort: at most 27 parts
      for (int m = i; m > 0 && last[m].bound2 < last[m - 1].bound2; --m) std::swap(last[m], last[m - 1]);
    for (int a = 0; a < first_count; ++a) {
      const double room2 = r2_ - first[a].bound2;
      const std::uint64_t key = q.base + first[a].key;
      for (int b = 0; b < last_count && last[b].bound2 < room2; ++b)
        if (leaf(key + last[b].key, first[a].bound2 + last[b].bound2)) return true;
    }
    return false;
  }

  bool cell_conflicts(const CellRecord<N>& cell, const double* x) const {
    const std::uint32_t count = load_acquire(cell.count);
    for (std::uint32_t s = 0; s < std::min<std::uint32_t>(count, kSlots<N>); ++s)
      if (closer_than_radius(x, cell.x[s])) return true;
    if (count <= kSlots<N>) return false;
    for (std::uint32_t o = load_acquire(cell.overflow); o != 0;) {
      const OverflowPoint<N>& p = overflow_[o - 1];
      if (closer_than_radius(x, p.x)) return true;
      o = p.next;
    }
    return false;
  }

#if defined(__SSE2__)
  // The squared per-axis distances two axes at a time (the same values as below), summed in a tree:
  // within 2e-15 (relative) of the sum in axis order, all terms being >= 0, so a tree sum outside
  // r^2 (1 -+ 1e-12) decides as the sum in axis order does, and only the others take that sum. A
  // shorter chain of dependent additions, and half the instructions.
  bool closer_than_radius(const double* x, const double* y) const {
    const __m128d side = _mm_set1_pd(side_), sign = _mm_set1_pd(-0.0);
    __m128d acc = _mm_setzero_pd();
    for (int j = 0; j + 2 <= N; j += 2) {
      __m128d d = _mm_sub_pd(_mm_loadu_pd(x + j), _mm_loadu_pd(y + j));
      if (periodic_) {
        d = _mm_andnot_pd(sign, d);
        d = _mm_min_pd(_mm_sub_pd(side, d), d);  // per lane: side - d < d ? side - d : d
      }
      acc = _mm_add_pd(acc, _mm_mul_pd(d, d));
    }
    double tree = _mm_cvtsd_f64(acc) + _mm_cvtsd_f64(_mm_unpackhi_pd(acc, acc));
    if constexpr (N % 2 != 0) {
      double d = std::abs(x[N - 1] - y[N - 1]);
      if (periodic_) {
        const double e = side_ - d;
        d = e < d ? e : d;
      }
      tree += d * d;
    }
    if (tree < below_r2_) return true;
    if (tree >= above_r2_) return false;
    return closer_than_radius_in_order(x, y);
  }
#else
  bool closer_than_radius(const double* x, const double* y) const { return closer_than_radius_in_order(x, y); }
#endif

  bool closer_than_radius_in_order(const double* x, const double* y) const {
    double dist2 = 0.0;
    if (periodic_) {  // the minimum image
      // min(d, side - d) is d > side / 2 ? side - d : d to the bit (side - d is exact when d > side / 2,
      // and rounds to at least side / 2 >= d otherwise), without a branch to mispredict.
      for (int j = 0; j < N; ++j) {
        const double d = std::abs(x[j] - y[j]);
        const double e = side_ - d, m = e < d ? e : d;
        dist2 += m * m;
      }
      return dist2 < r2_;
    }
    for (int j = 0; j < N; ++j) dist2 += (x[j] - y[j]) * (x[j] - y[j]);
    return dist2 < r2_;
  }

  // The key offsets of the neighbouring cell below and above x's cell on axis j (modulo 2^64): across
  // the identified faces on the torus, from the first cell to the last and back.
  std::uint64_t step_down(const Query& q, int j) const {
    return periodic_ && q.cell[j] == 0 ? static_cast<std::uint64_t>(cells_per_axis_ - 1) * stride_[j] : -stride_[j];
  }
  std::uint64_t step_up(const Query& q, int j) const {
    return periodic_ && q.cell[j] + 1 == cells_per_axis_ ? -(static_cast<std::uint64_t>(cells_per_axis_ - 1) * stride_[j])
                                                         : stride_[j];
  }

  // Hashed: open addressing from packed cell coordinates (stored + 1; 0 marks an empty slot) to ids.
  // The key is published after its id, so a reader that finds it also finds the id.
  std::size_t id_of(std::uint64_t key) const {
    if (dense_) return key;
    for (std::size_t slot = mix64(key) & slot_mask_;; slot = (slot + 1) & slot_mask_) {
      const std::uint64_t stored = load_acquire(keys_.data()[slot]);
      if (stored == key + 1) return ids_.data()[slot];
      if (stored == 0) return kNoCell;
    }
  }

  std::size_t id_or_add(std::uint64_t key) {
    std::size_t slot = mix64(key) & slot_mask_;
    for (; keys_.data()[slot] != 0; slot = (slot + 1) & slot_mask_)
      if (keys_.data()[slot] == key + 1) return ids_.data()[slot];
    ids_.data()[slot] = static_cast<std::uint32_t>(hashed_cells_);
    store_release(keys_.data()[slot], key + 1);
    return hashed_cells_++;
  }

  double lo_, cell_, r2_;
  // r^2 (1 -+ 1e-12): tree sums below or above them decide without the sum in axis order (outside
  // [1e-250, 1e250], where squares may underflow or overflow, every sum takes it).
  double below_r2_, above_r2_;
  bool dense_;
  bool periodic_;  // the torus: neighbours across the identified faces, minimum-image distances
  double side_;
  std::int64_t cells_per_axis_;
  std::uint64_t stride_[N];
  // By cell id: the record, a bit that says whether it holds a point (1/1000 of the records: it stays
  // cached), and 1 + the index of the last point put in it (for conflicts_since; inserting thread).
  ZeroedPages<CellRecord<N>> records_;
  ZeroedPages<std::uint64_t> occupied_;
  ZeroedPages<std::uint32_t> last_point_;
  StableArray<OverflowPoint<N>> overflow_;
  std::size_t overflow_count_ = 0;
  ZeroedPages<std::uint64_t> keys_;
  ZeroedPages<std::uint32_t> ids_;
  std::size_t slot_mask_ = 0;
  std::size_t hashed_cells_ = 0;
};

// Dense when the array of all cells costs at most 8x the points' coordinates plus 16 bytes each
// (saturated sets hold about one point per cell), or 64 MiB.
template <int N>
bool use_dense_grid(const PoissonDiskOptions& options, std::uint64_t max_points) {
  if (options.grid != PoissonDiskGrid::automatic) return options.grid == PoissonDiskGrid::dense;
  const double cells = std::pow(std::max(1.0, std::ceil(options.domain.side / options.radius)), N);
  const double bytes_per_cell = sizeof(CellRecord<N>) + 4.0 + 1.0 / 8.0;
  const double expected_points = std::min(static_cast<double>(max_points), cells);
  return cells * bytes_per_cell <= std::max(64.0 * (1 << 20), 8.0 * expected_points * (8.0 * N + 16.0));
}

// ---------------------------------------------------------------------------------------------------
// The queue, and its entries' candidates thrown ahead by helper threads.

// A placed point, kept where helper threads can read it while more are placed.
template <int N>
struct Point {
  double x[N];
};

// A queued visit: the point and how many visits it had before.
struct Entry {
  std::uint32_t point;
  std::uint32_t visit;
};

// Entries per block, the unit a helper thread claims, and blocks a helper may run ahead of the
// committing thread (the ring of results).
constexpr std::uint64_t kEntriesPerBlock = 8;
constexpr std::uint64_t kBlocksAhead = 32;
// Points placed since a survivor's check that the committing thread compares directly; beyond this
// it asks the grid.
constexpr std::uint32_t kDirectRecentPoints = 48;

// The survivors of a block's entries: candidates in the domain and clear of the `snapshot` points
// placed first (at least), in the order thrown.
template <int N>
struct Block {
  static constexpr int kFree = 0, kClaimed = 1, kDone = 2;
  std::atomic<int> state{kFree};
  std::uint32_t snapshot = 0;
  std::vector<double> coordinates;   // survivors x N
  std::vector<std::uint32_t> thrown;  // the survivor's candidate number t within its entry
  std::uint32_t ends[kEntriesPerBlock] = {};  // entry i's survivors end at ends[i]
};

template <int N>
class QueueProcess {
 public:
  QueueProcess(const PoissonDiskOptions& options, std::uint64_t seed, std::uint64_t max_points,
               const FractionProgress& progress, PointSet& points)
      : domain_(options.domain),
        r_(options.radius),
        k_(static_cast<std::uint64_t>(options.candidates)),
        max_points_(max_points),
        key_(stream_key(seed, Stream::poisson_disk)),
        normal_(NormalZiggurat::instance()),
        grid_(options.domain, options.radius, use_dense_grid<N>(options, max_points), max_points),
        ticker_(progress, max_points),
        output_(points.coordinates),
        blocks_(new Block<N>[kBlocksAhead]) {}

  // Runs the queue to its end with `threads` threads, then writes the points to the output; returns
  // candidates thrown, and whether it stopped at max_points.
  std::pair<std::uint64_t, bool> run(int threads) {
    place_first_point();
    if (threads <= 1) {
      commit_all();
    } else {
      std::exception_ptr failure;
#pragma omp parallel num_threads(threads)
      {
        try {
          if (omp_get_thread_num() == 0) {
            commit_all();
            finished_.store(true);
            wake_helpers();
          } else {
            help();
          }
        } catch (...) {
#pragma omp critical(dfvn_poisson_disk_failure)
          if (!failure) failure = std::current_exception();
          failed_.store(true);
          finished_.store(true);
          wake_helpers();
        }
      }
      if (failure) std::rethrow_exception(failure);
    }
    output_.resize(points_ * N);  // once, at its size: no copies of a growing vector
    for (std::size_t p = 0; p < points_; ++p) std::copy(points_store_[p].x, points_store_[p].x + N, output_.data() + p * N);
    return {candidates_tried_, stopped_};
  }

 private:
  // The first point: uniform in the domain (by rejection for a ball), from the words of (seed, 0, attempt).
  void place_first_point() {
    for (std::uint64_t attempt = 0;; ++attempt) {
      RandomWords words{hash_combine(hash_combine(key_, 0), attempt)};
      double x[N];
      for (int j = 0; j < N; ++j) x[j] = domain_.lo + domain_.side * bits_to_unit(words());
      if (domain_.contains(x, N)) {
        place(x);
        break;
      }
    }
    stopped_ = points_ >= max_points_;
  }

  void place(const double* x) {
    const auto index = static_cast<std::uint32_t>(points_);
    ticker_.tick(points_ + 1);
    std::copy(x, x + N, points_store_.slot(index).x);
    grid_.insert(x, index);
    queue_.slot(queued_++) = Entry{index, 0};
    ++points_;
    points_published_.store(static_cast<std::uint32_t>(points_), std::memory_order_release);
  }

  // Candidate t of visit v of point i comes from the words of (seed, i + 1, v, t), so the candidates
  // are the same whoever throws them. Appends the survivors: in the domain, and clear of the points
  // the grid holds now.
  void throw_candidates(const Entry& entry, std::vector<double>& survivors, std::vector<std::uint32_t>& thrown) const {
    const std::uint64_t visit_key = hash_combine(hash_combine(key_, std::uint64_t{entry.point} + 1), entry.visit);
    const double* parent = points_store_[entry.point].x;
    // One candidate behind: candidate t's own cell is fetched while t + 1 is drawn.
    double candidates[2][N];
    typename CellGrid<N>::Query queries[2];
    bool pending = false;  // candidate t - 1 is in the domain and waits for its check
    for (std::uint64_t t = 0; t <= k_; ++t) {
      double* candidate = candidates[t % 2];
      bool inside = false;
      if (t < k_) {
        RandomWords words{hash_combine(visit_key, t)};
        uniform_in_annulus<N>(words, normal_, r_, candidate);
        for (int j = 0; j < N; ++j) candidate[j] += parent[j];
        if (domain_.periodic()) domain_.wrap(candidate, N);  // the torus: every candidate is in it
        inside = domain_.contains(candidate, N);
        if (inside) queries[t % 2] = grid_.prepare(candidate);
      }
      const double* previous = candidates[(t + 1) % 2];
      if (pending && !grid_.conflicts(queries[(t + 1) % 2])) {
        survivors.insert(survivors.end(), previous, previous + N);
        thrown.push_back(static_cast<std::uint32_t>(t - 1));
      }
      pending = inside;
    }
  }

  void compute_block(std::uint64_t b) {
    Block<N>& block = blocks_[b % kBlocksAhead];
    block.snapshot = points_published_.load(std::memory_order_acquire);
    block.coordinates.clear();
    block.thrown.clear();
    for (std::uint64_t i = 0; i < kEntriesPerBlock; ++i) {
      throw_candidates(queue_[b * kEntriesPerBlock + i], block.coordinates, block.thrown);
      block.ends[i] = static_cast<std::uint32_t>(block.thrown.size());
    }
    block.state.store(Block<N>::kDone, std::memory_order_release);
  }

  // Claims the next whole block within reach of the committing thread, if any.
  bool try_claim(std::uint64_t& b) {
    std::uint64_t next = next_claim_.load(std::memory_order_acquire);
    if (next >= committed_blocks_.load(std::memory_order_acquire) + kBlocksAhead ||
        (next + 1) * kEntriesPerBlock > queue_published_.load(std::memory_order_acquire))
      return false;
    if (!next_claim_.compare_exchange_strong(next, next + 1, std::memory_order_acq_rel)) return false;
    blocks_[next % kBlocksAhead].state.store(Block<N>::kClaimed, std::memory_order_relaxed);
    b = next;
    return true;
  }

  // A helper that finds nothing to claim sleeps until the committing thread commits or queues more
  // (spinning would take the time of the committing thread when both share a core, as on a busy
  // machine). Sleepers are counted before the epoch is read again, and the committing thread bumps
  // the epoch before it reads the count (both sequentially consistent), so no wake-up is lost.
  void help() {
    while (!finished_.load(std::memory_order_acquire)) {
      const std::uint64_t seen = epoch_.load();
      std::uint64_t b;
      if (try_claim(b)) {
        compute_block(b);
        continue;
      }
      sleepers_.fetch_add(1);
      if (!finished_.load() && epoch_.load() == seen) epoch_.wait(seen);
      sleepers_.fetch_sub(1);
    }
  }

  void wake_helpers() {
    epoch_.fetch_add(1);
    if (sleepers_.load() > 0) epoch_.notify_all();
  }

  // In order, the decisions of the sequential process: a survivor is placed if no point placed since
  // its check is closer than r.
  bool clear_since(const double* x, std::uint32_t since) const {
    if (points_ - since <= kDirectRecentPoints) {
      for (std::size_t p = since; p < points_; ++p)
        if (domain_.distance2(x, points_store_[p].x, N) < r_ * r_) return false;  // minimum image on the torus
      return true;
    }
    return !grid_.conflicts_since(x, since);
  }

  // One entry's survivors, in order; false once max_points are placed.
  bool commit_entry(std::uint64_t e, const double* survivors, const std::uint32_t* thrown, std::size_t count,
                    std::uint32_t snapshot) {
    const Entry entry = queue_[e];
    bool placed = false;
    for (std::size_t m = 0; m < count; ++m) {
      const double* x = survivors + m * N;
      if (!clear_since(x, snapshot)) continue;
      place(x);
      placed = true;
      if (points_ >= max_points_) {
        candidates_tried_ = e * k_ + thrown[m] + 1;
        return false;
      }
    }
    if (placed) {  // the point is queued again, after the points it placed
      queue_.slot(queued_++) = Entry{entry.point, entry.visit + 1};
    }
    queue_published_.store(queued_, std::memory_order_release);
    return true;
  }

  void commit_all() {
    queue_published_.store(queued_, std::memory_order_release);
    std::vector<double> survivors;
    std::vector<std::uint32_t> thrown;
    for (std::uint64_t b = 0; !stopped_ && b * kEntriesPerBlock < queued_; ++b) {
      Block<N>& block = blocks_[b % kBlocksAhead];
      std::uint64_t mine = b;
      if (next_claim_.compare_exchange_strong(mine, b + 1, std::memory_order_acq_rel)) {
        // Nobody threw this block's candidates: throw them entry by entry, against all points so far.
        for (std::uint64_t e = b * kEntriesPerBlock; e < (b + 1) * kEntriesPerBlock && e < queued_ && !stopped_; ++e) {
          survivors.clear();
          thrown.clear();
          const auto snapshot = static_cast<std::uint32_t>(points_);
          throw_candidates(queue_[e], survivors, thrown);
          stopped_ = !commit_entry(e, survivors.data(), thrown.data(), thrown.size(), snapshot);
        }
      } else {
        // A helper has it: while it is not done, throw blocks further ahead instead of waiting.
        for (int idle = 0; block.state.load(std::memory_order_acquire) != Block<N>::kDone;) {
          if (failed_.load(std::memory_order_acquire)) return;  // the helper's exception is rethrown
          std::uint64_t ahead;
          if (try_claim(ahead)) {
            compute_block(ahead);
            idle = 0;
          } else if (++idle < 64) {
            __builtin_ia32_pause();
          } else {
            std::this_thread::yield();
          }
        }
        for (std::uint64_t i = 0; i < kEntriesPerBlock && !stopped_; ++i) {
          const std::uint32_t begin = i == 0 ? 0 : block.ends[i - 1];
          stopped_ = !commit_entry(b * kEntriesPerBlock + i, block.coordinates.data() + std::size_t{begin} * N,
                                   block.thrown.data() + begin, block.ends[i] - begin, block.snapshot);
        }
      }
      block.state.store(Block<N>::kFree, std::memory_order_relaxed);
      committed_blocks_.store(b + 1, std::memory_order_release);
      wake_helpers();
    }
    if (!stopped_) candidates_tried_ = queued_ * k_;  // the queue emptied: every entry was visited
  }

  const Domain domain_;
  const double r_;
  const std::uint64_t k_;
  const std::uint64_t max_points_;
  const std::uint64_t key_;
  const NormalZiggurat& normal_;
  CellGrid<N> grid_;
  const ProgressTicker ticker_;
  Coordinates& output_;
  StableArray<Point<N>> points_store_;  // written by the committing thread, read by all
  StableArray<Entry> queue_;
  std::unique_ptr<Block<N>[]> blocks_;
  // Committing thread only.
  std::uint64_t points_ = 0, queued_ = 0, candidates_tried_ = 0;
  bool stopped_ = false;
  // Shared.
  std::atomic<std::uint32_t> points_published_{0};
  std::atomic<std::uint64_t> queue_published_{0};
  std::atomic<std::uint64_t> next_claim_{0};
  std::atomic<std::uint64_t> committed_blocks_{0};
  std::atomic<bool> finished_{false}, failed_{false};
  std::atomic<std::uint64_t> epoch_{0};  // bumped whenever the committing thread commits a block
  std::atomic<int> sleepers_{0};
};

}  // namespace

template <int N>
PoissonDiskResult poisson_disk(const PoissonDiskOptions& options, std::uint64_t seed, int threads,
                               const FractionProgress& progress) {
  options.validate(N);
  check_thread_count(threads);
  const std::uint64_t max_points = std::min<std::uint64_t>(options.max_points, std::numeric_limits<std::uint32_t>::max() - 1);
  PoissonDiskResult result;
  result.points = PointSet{N, {}, options.domain};
  if (max_points == 0) return result;
  QueueProcess<N> process(options, seed, max_points, progress, result.points);
  const auto [candidates, stopped] = process.run(resolve_threads(threads));
  result.candidates_tried = candidates;
  result.reached_max_points = stopped;
  result.radius = options.radius;
  return result;
}

PoissonDiskResult poisson_disk(int dimension, const PoissonDiskOptions& options, std::uint64_t seed, int threads,
                               const FractionProgress& progress) {
  return dispatch_dimension(dimension, [&]<int N>() { return poisson_disk<N>(options, seed, threads, progress); });
}

namespace {
// points * r^N / volume of saturated sets on the unit torus, k = 30: the median of 5 seeds at about
// 2^17 points (2^21 in 2D), data/poisson_disk_saturation.md (bench/pds_saturation).
constexpr double kSaturationDensity2 = 0.623730, kSaturationDensity3 = 0.587964, kSaturationDensity4 = 0.582974,
                 kSaturationDensity5 = 0.612240, kSaturationDensity6 = 0.681006, kSaturationDensity7 = 0.800076,
                 kSaturationDensity8 = 0.986418;
}  // namespace

namespace {
// The boundary term B of saturated sets in the unit cube and ball, whose faces hold more points than the
// torus' density: points = D V / r^N (1 + B (2N / side) r) (2N / side: the boundary's area over the
// volume, for the cube and its inscribed ball alike); the median of 3 seeds at about 2^17 points,
// data/poisson_disk_saturation.md (bench/pds_saturation). Index: the dimension.
constexpr double kCubeBoundaryTerm[9] = {0, 0, 0.3285, 0.2091, 0.1878, 0.1715, 0.1554, 0.1379, 0.1198};
constexpr double kBallBoundaryTerm[9] = {0, 0, 0.1818, 0.2042, 0.1929, 0.1751, 0.1595, 0.1460, 0.1343};
}  // namespace

double poisson_disk_saturation_points(int dimension, const Domain& domain, double radius) {
  const double boundary_term = domain.kind == DomainKind::cube   ? kCubeBoundaryTerm[dimension]
                               : domain.kind == DomainKind::ball ? kBallBoundaryTerm[dimension]
                                                                 : 0.0;
  return poisson_disk_saturation_density(dimension) * domain.measure(dimension) / std::pow(radius, dimension) *
         (1.0 + boundary_term * 2.0 * dimension / domain.side * radius);
}

double poisson_disk_saturation_density(int dimension) {
  // points * r^N / volume of saturated sets on the unit torus, k = 30 (data/poisson_disk_saturation.md).
  switch (dimension) {
    case 2: return kSaturationDensity2;
    case 3: return kSaturationDensity3;
    case 4: return kSaturationDensity4;
    case 5: return kSaturationDensity5;
    case 6: return kSaturationDensity6;
    case 7: return kSaturationDensity7;
    case 8: return kSaturationDensity8;
    default: throw std::invalid_argument("Poisson disk sampling covers dimensions 2..8, not " + std::to_string(dimension));
  }
}

PoissonDiskResult poisson_disk_reaching(int dimension, const PoissonDiskOptions& options, std::uint64_t seed, int threads,
                                        const FractionProgress& progress) {
  const std::uint64_t target = options.max_points;
  if (target == 0 || target == std::numeric_limits<std::uint64_t>::max())
    throw std::invalid_argument("a Poisson disk radius search needs the count to reach (max_points)");
  const double n = static_cast<double>(target);
  PoissonDiskOptions run = options;
  // The saturation radius, where poisson_disk_saturation_points gives n: the torus' r = (D V / n)^(1/N),
  // then the boundary term's few per cent by fixed-point steps (each shrinks the error by about 1/N).
  double radius = std::pow(poisson_disk_saturation_density(dimension) * options.domain.measure(dimension) / n, 1.0 / dimension);
  for (int step = 0; step < 20; ++step)
    radius *= std::pow(poisson_disk_saturation_points(dimension, options.domain, radius) / n, 1.0 / dimension);
  run.radius = radius * (1.0 - kReachingMargin);  // the first run: kReachingMargin below it
  if (options.domain.periodic()) run.radius = std::min(run.radius, 0.49 * options.domain.side);
  // One stage for all the runs: the fraction never goes back when a run starts again.
  double reported = 0.0;
  const FractionProgress monotone = [&](double f) {
    reported = std::max(reported, f);
    if (progress) progress(reported);
  };
  for (int attempt = 1; attempt <= kMaxReachingRuns; ++attempt) {
    // The first run takes the seed itself (so --pds-radius with the radius found gives the same set), a
    // later run a seed of its own, (seed, attempt): its radius depends on the runs before.
    const std::uint64_t run_seed = attempt == 1 ? seed : hash_combine(seed, static_cast<std::uint64_t>(attempt));
    PoissonDiskResult result = poisson_disk(dimension, run, run_seed, threads, monotone);
    result.runs = attempt;
    if (result.reached_max_points) return result;
    // Saturated with m < n points: m r^N ~ n r'^N.
    const double m = static_cast<double>(std::max<std::size_t>(result.points.size(), 1));
    run.radius *= std::pow(m / n, 1.0 / dimension) * (1.0 - kReachingMargin);
  }
  throw std::runtime_error("Poisson disk sampling did not reach " + std::to_string(target) + " points in " +
                           std::to_string(kMaxReachingRuns) + " runs of decreasing radius");
}

}  // namespace dfvn
