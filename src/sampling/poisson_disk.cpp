#include "sampling/poisson_disk.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/dimension.hpp"
#include "core/hash.hpp"
#include "core/parallel.hpp"

namespace dfvn {

void PoissonDiskOptions::validate(int dimension) const {
  if (!std::isfinite(radius) || radius <= 0.0) throw std::invalid_argument("PDS radius must be a finite number > 0");
  if (candidates < 1) throw std::invalid_argument("PDS candidates must be at least 1");
  if (!std::isfinite(domain.lo) || !std::isfinite(domain.side) || domain.side <= 0.0)
    throw std::invalid_argument("PDS domain must be a finite box with positive side");
  const double cells = std::ceil(domain.side / radius);
  const double max_cells = std::ldexp(1.0, 64 / dimension) - 1.0;
  if (cells > max_cells)
    throw std::invalid_argument("PDS radius " + std::to_string(radius) + " is too small for a domain of side " +
                                std::to_string(domain.side) + " in " + std::to_string(dimension) +
                                "D (at most " + std::to_string(static_cast<long long>(max_cells)) +
                                " cells of side r per axis)");
}

namespace {

// SplitMix64 (Steele, Lea and Flood 2014) from a hashed state: the random words of one candidate.
struct RandomWords {
  std::uint64_t state;
  std::uint64_t operator()() {
    state += kGoldenGamma;
    return mix64(state);
  }
};

// Standard normal numbers by the ziggurat (Marsaglia and Tsang 2000, "The ziggurat method for
// generating random variables"): the area under f(x) = exp(-x^2/2), x >= 0, is covered by 256 strips
// of equal area v; strip 0 is the base [0, r] x [0, f(r)] with the tail x > r, strip i >= 1 spans
// heights [f(x_i), f(x_{i+1})] and widths [0, x_i]. A uniform point of a uniform strip lies under the
// curve, without any further test, in ~99% of draws; only the strips' right ends need exp() and the
// tail log(). Exact: every accepted x has the half-normal density, and a random sign makes it normal.
class NormalZiggurat {
 public:
  static constexpr int kStrips = 256;

  static const NormalZiggurat& instance() {
    static const NormalZiggurat ziggurat;
    return ziggurat;
  }

  // One word in ~99% of draws: bits 0-7 pick the strip, bit 8 the sign, bits 11-63 the abscissa.
  template <class Words>
  double operator()(Words& words) const {
    for (;;) {
      const std::uint64_t w = words();
      const auto strip = static_cast<int>(w & 0xFF);
      const double sign = (w & 0x100) != 0 ? -1.0 : 1.0;
      const double x = bits_to_unit(w) * x_[strip];
      if (x < x_[strip + 1]) return sign * x;  // inside the part of the strip wholly under the curve
      if (strip == 0) {                        // the tail x > r (Marsaglia 1964)
        double a, b;
        do {
          a = -std::log(1.0 - bits_to_unit(words())) / tail_;
          b = -std::log(1.0 - bits_to_unit(words()));
        } while (2.0 * b < a * a);
        return sign * (tail_ + a);
      }
      if (f_[strip] + bits_to_unit(words()) * (f_[strip + 1] - f_[strip]) < std::exp(-0.5 * x * x)) return sign * x;
    }
  }

  double tail_start() const { return tail_; }

 private:
  static double f(double x) { return std::exp(-0.5 * x * x); }
  static double f_inverse(double y) { return std::sqrt(-2.0 * std::log(y)); }
  // The area of every strip when the base strip starts at r: r f(r) plus the tail's integral.
  static double strip_area(double r) { return r * f(r) + std::sqrt(0.5 * std::numbers::pi) * std::erfc(r / std::numbers::sqrt2); }

  // Stacks strips of area v(r) from x_1 = r upwards; returns the top strip's area minus v: > 0 when
  // r is too large (the strips are too thin to reach the top), < 0 when they overshoot it.
  double stack(double r) {
    const double v = strip_area(r);
    x_[0] = v / f(r);
    x_[1] = r;
    for (int i = 1; i + 1 < kStrips; ++i) {
      const double height = v / x_[i] + f(x_[i]);
      if (height >= 1.0) return -1.0;
      x_[i + 1] = f_inverse(height);
    }
    x_[kStrips] = 0.0;
    return x_[kStrips - 1] * (1.0 - f(x_[kStrips - 1])) - v;
  }

  // r solves stack(r) = 0 (bisection; 3.6541528853610088 for 256 strips, as Marsaglia and Tsang give).
  NormalZiggurat() {
    double low = 2.0, high = 5.0;
    for (int i = 0; i < 200 && high - low > 0.0; ++i) {
      const double mid = 0.5 * (low + high);
      if (mid == low || mid == high) break;
      (stack(mid) > 0.0 ? high : low) = mid;
    }
    tail_ = high;
    stack(tail_);
    for (int i = 0; i <= kStrips; ++i) f_[i] = f(x_[i]);
  }

  double x_[kStrips + 1];  // x_[0] = v / f(r) (the base strip's width with its tail), x_[1] = r > ... > x_[256] = 0
  double f_[kStrips + 1];  // f(x_i); f_[256] = 1
  double tail_ = 0.0;      // r
};

// A candidate offset d uniform in the volume of the annulus r <= |d| <= 2r, exactly: N + 2 normal
// numbers g give a point uniform on the sphere S^(N+1), and its first N coordinates are uniform in
// the N-ball (Voelker, Gosmann and Stewart 2017, "Efficiently sampling vectors and coordinates from
// the n-sphere and n-ball"); scaled by 2r and rejected when inside radius r (a fraction 2^-N), they
// are uniform in the annulus. No logarithm, cosine or power per candidate.
template <int N>
void annulus_offset(RandomWords& words, const NormalZiggurat& normal, double radius, double* offset) {
  for (;;) {
    double g[N + 2];
    double inner2 = 0.0;
    for (int j = 0; j < N; ++j) {
      g[j] = normal(words);
      inner2 += g[j] * g[j];
    }
    g[N] = normal(words);
    g[N + 1] = normal(words);
    const double all2 = inner2 + g[N] * g[N] + g[N + 1] * g[N + 1];
    if (!(all2 > 0.0) || 4.0 * inner2 < all2) continue;  // |d|^2 = 4 r^2 inner2 / all2 < r^2
    const double scale = 2.0 * radius / std::sqrt(all2);
    for (int j = 0; j < N; ++j) offset[j] = scale * g[j];
    return;
  }
}

// Points stored in the cell of the grid: a cell's first kSlots points inline (coordinates in cell
// order, so a cell is one or two cache lines), further ones in a shared overflow list. Saturated
// Bridson sets hold 0.7 points per cell of side r in 2D-5D and 1-2 in 7D-8D (their densities).
template <int N>
inline constexpr int kSlots = N <= 4 ? 2 : 1;

template <int N>
class CellGrid {
 public:
  CellGrid(const Box& domain, double radius, bool dense)
      : lo_(domain.lo), cell_(radius), r2_(radius * radius), dense_(dense) {
    cells_per_axis_ = static_cast<std::int64_t>(std::max(1.0, std::ceil(domain.side / radius)));
    if (dense_) {
      std::uint64_t stride = 1;
      for (int j = N - 1; j >= 0; --j) {
        stride_[j] = stride;
        stride *= static_cast<std::uint64_t>(cells_per_axis_);
      }
      cell_count_ = stride;
      counts_.assign(cell_count_, 0);
      stamps_.assign(cell_count_, 0);
      overflow_head_.assign(cell_count_, 0);
      dense_slots_.reset(new double[cell_count_ * kSlots<N> * N]);  // untouched until a point lands: no zero fill
      slots_ = dense_slots_.get();
    } else {
      int bits = 1;
      while ((std::int64_t{1} << bits) - 1 < cells_per_axis_) ++bits;
      for (int j = 0; j < N; ++j) stride_[j] = std::uint64_t{1} << (bits * (N - 1 - j));
      keys_.assign(1024, kEmpty);
      ids_.assign(1024, 0);
    }
  }

  // True if a stored point is closer than r to x; with kBatchOnly, only points in cells that
  // received a point during `batch` are compared.
  template <bool kBatchOnly = false>
  bool conflicts(const double* x, std::uint32_t batch = 0) const {
    Query q;
    q.x = x;
    q.batch = batch;
    for (int j = 0; j < N; ++j) {
      q.cell[j] = cell_of(x[j]);
      // Distances to the lower and upper faces of x's cell, shrunk by a hair so that rounding in
      // cell_of() can never prune a cell that holds a conflicting point.
      const double offset = x[j] - (lo_ + static_cast<double>(q.cell[j]) * cell_);
      q.below2[j] = square(std::max(0.0, offset - 1e-12 * cell_));
      q.above2[j] = square(std::max(0.0, cell_ - offset - 1e-12 * cell_));
    }
    return visit<kBatchOnly, 0>(0, 0.0, q);
  }

  void insert(const double* x, std::uint32_t batch) {
    std::uint64_t key = 0;
    for (int j = 0; j < N; ++j) key += static_cast<std::uint64_t>(cell_of(x[j])) * stride_[j];
    const std::size_t id = dense_ ? key : find_or_add(key);
    const unsigned count = counts_[id];
    assert(count < 0xFFFF);  // a cell of side r holds fewer than (4 / V_N(1)) 2^(2N) points (disjoint r/2-balls)
    if (count < kSlots<N>) {
      std::copy(x, x + N, slots_ + (id * kSlots<N> + count) * N);
    } else {
      overflow_.insert(overflow_.end(), x, x + N);
      overflow_next_.push_back(overflow_head_[id]);
      overflow_head_[id] = static_cast<std::uint32_t>(overflow_next_.size());  // 1-based; 0 ends a list
    }
    counts_[id] = static_cast<std::uint16_t>(count + 1);
    stamps_[id] = batch;
  }

  std::uint64_t cell_count() const { return cell_count_; }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};  // packed cell coordinates never are all ones
  static double square(double v) { return v * v; }

  struct Query {
    const double* x;
    std::uint32_t batch;
    std::int64_t cell[N];
    double below2[N], above2[N];
  };

  std::int64_t cell_of(double v) const {
    const auto c = static_cast<std::int64_t>(std::floor((v - lo_) / cell_));
    return std::clamp<std::int64_t>(c, 0, cells_per_axis_ - 1);
  }

  // Depth-first over axes: offset 0, then the nearer and the farther neighbour along `Axis`, keeping
  // the squared distance from x to the cell box so far; a branch whose bound reaches r^2 cannot hold
  // a conflicting point. The last axis varies fastest in memory, so sibling leaves are adjacent.
  template <bool kBatchOnly, int Axis>
  bool visit(std::uint64_t key, double bound2, const Query& q) const {
    if constexpr (Axis == N) {
      return cell_conflicts<kBatchOnly>(key, q);
    } else {
      const std::int64_t c = q.cell[Axis];
      const std::uint64_t stride = stride_[Axis];
      const std::uint64_t here = key + static_cast<std::uint64_t>(c) * stride;
      if (visit<kBatchOnly, Axis + 1>(here, bound2, q)) return true;
      const double down = bound2 + q.below2[Axis], up = bound2 + q.above2[Axis];
      const bool has_down = c > 0 && down < r2_, has_up = c + 1 < cells_per_axis_ && up < r2_;
      if (down <= up) {
        if (has_down && visit<kBatchOnly, Axis + 1>(here - stride, down, q)) return true;
        if (has_up && visit<kBatchOnly, Axis + 1>(here + stride, up, q)) return true;
      } else {
        if (has_up && visit<kBatchOnly, Axis + 1>(here + stride, up, q)) return true;
        if (has_down && visit<kBatchOnly, Axis + 1>(here - stride, down, q)) return true;
      }
      return false;
    }
  }

  template <bool kBatchOnly>
  bool cell_conflicts(std::uint64_t key, const Query& q) const {
    std::size_t id = key;
    if (!dense_) {
      id = find(key);
      if (id == kNoCell) return false;
    }
    const unsigned count = counts_[id];
    if (count == 0) return false;
    if (kBatchOnly && stamps_[id] != q.batch) return false;
    const double* p = slots_ + id * kSlots<N> * N;
    for (unsigned s = 0; s < std::min<unsigned>(count, kSlots<N>); ++s, p += N)
      if (closer_than_radius(q.x, p)) return true;
    for (std::uint32_t o = overflow_head_[id]; o != 0; o = overflow_next_[o - 1])
      if (closer_than_radius(q.x, overflow_.data() + std::size_t{o - 1} * N)) return true;
    return false;
  }

  bool closer_than_radius(const double* x, const double* y) const {
    double dist2 = 0.0;
    for (int j = 0; j < N; ++j) dist2 += (x[j] - y[j]) * (x[j] - y[j]);
    return dist2 < r2_;
  }

  // The hashed grid: open addressing from packed cell coordinates to cell ids in order of first use.
  static constexpr std::size_t kNoCell = ~std::size_t{0};

  std::size_t find(std::uint64_t key) const {
    const std::size_t mask = keys_.size() - 1;
    for (std::size_t slot = mix64(key) & mask;; slot = (slot + 1) & mask) {
      if (keys_[slot] == key) return ids_[slot];
      if (keys_[slot] == kEmpty) return kNoCell;
    }
  }

  std::size_t find_or_add(std::uint64_t key) {
    const std::size_t found = find(key);
    if (found != kNoCell) return found;
    if (2 * (cell_count_ + 1) > keys_.size()) grow();
    const std::size_t mask = keys_.size() - 1;
    std::size_t slot = mix64(key) & mask;
    while (keys_[slot] != kEmpty) slot = (slot + 1) & mask;
    keys_[slot] = key;
    ids_[slot] = cell_count_;
    counts_.push_back(0);
    stamps_.push_back(0);
    overflow_head_.push_back(0);
    hashed_slots_.resize(hashed_slots_.size() + kSlots<N> * N);
    slots_ = hashed_slots_.data();
    return cell_count_++;
  }

  void grow() {
    std::vector<std::uint64_t> old_keys(keys_.size() * 2, kEmpty);
    std::vector<std::size_t> old_ids(ids_.size() * 2, 0);
    old_keys.swap(keys_);
    old_ids.swap(ids_);
    const std::size_t mask = keys_.size() - 1;
    for (std::size_t i = 0; i < old_keys.size(); ++i) {
      if (old_keys[i] == kEmpty) continue;
      std::size_t slot = mix64(old_keys[i]) & mask;
      while (keys_[slot] != kEmpty) slot = (slot + 1) & mask;
      keys_[slot] = old_keys[i];
      ids_[slot] = old_ids[i];
    }
  }

  double lo_, cell_, r2_;
  bool dense_;
  std::int64_t cells_per_axis_;
  std::uint64_t stride_[N];
  std::uint64_t cell_count_ = 0;  // dense: all cells; hashed: the occupied ones
  std::vector<std::uint16_t> counts_;
  std::vector<std::uint32_t> stamps_;  // the batch that last put a point in the cell
  std::vector<std::uint32_t> overflow_head_;
  std::unique_ptr<double[]> dense_slots_;
  std::vector<double> hashed_slots_;
  double* slots_ = nullptr;  // cell id x kSlots x N
  std::vector<double> overflow_;  // points x N
  std::vector<std::uint32_t> overflow_next_;
  std::vector<std::uint64_t> keys_;
  std::vector<std::size_t> ids_;
};

// Dense when the array of all cells costs at most ~4x the coordinates of the points it will hold
// (saturated sets hold about one point per cell), or 64 MiB.
template <int N>
bool use_dense_grid(const PoissonDiskOptions& options, std::uint64_t max_points) {
  if (options.grid != PoissonDiskGrid::automatic) return options.grid == PoissonDiskGrid::dense;
  const double cells = std::pow(std::max(1.0, std::ceil(options.domain.side / options.radius)), N);
  const double bytes_per_cell = 8.0 * kSlots<N> * N + 10.0;
  const double expected_points = std::min(static_cast<double>(max_points), cells);
  return cells * bytes_per_cell <= std::max(64.0 * (1 << 20), 4.0 * expected_points * 8.0 * N);
}

// The survivors of a run of consecutive queued points: candidates in the domain and clear of the
// points placed before the batch, in the order thrown.
template <int N>
struct Survivors {
  std::vector<double> coordinates;       // survivors x N
  std::vector<std::uint64_t> thrown_by;  // queue entry x candidates + t
  void clear() {
    coordinates.clear();
    thrown_by.clear();
  }
};

// Queue entries per unit of parallel work, and per batch: the points a batch checks against are up
// to one batch old, so a smaller batch wastes fewer candidates on conflicts found only in order.
constexpr std::uint64_t kEntriesPerChunk = 32;
constexpr std::uint64_t kEntriesPerBatch = 1024;

}  // namespace

template <int N>
PoissonDiskResult poisson_disk(const PoissonDiskOptions& options, std::uint64_t seed, int threads,
                               const FractionProgress& progress) {
  options.validate(N);
  check_thread_count(threads);
  const int thread_count = resolve_threads(threads);
  const Box& box = options.domain;
  const double r = options.radius;
  const auto k = static_cast<std::uint64_t>(options.candidates);
  const std::uint64_t max_points = std::min<std::uint64_t>(options.max_points, std::numeric_limits<std::uint32_t>::max() - 1);
  PoissonDiskResult result;
  result.points = PointSet{N, {}, box};
  if (max_points == 0) return result;
  std::vector<double>& coordinates = result.points.coordinates;
  CellGrid<N> grid(box, r, use_dense_grid<N>(options, max_points));
  const NormalZiggurat& normal = NormalZiggurat::instance();
  const std::uint64_t key = stream_key(seed, Stream::poisson_disk);
  const ProgressTicker ticker(progress, max_points);
  std::uint32_t batch = 0;
  auto add = [&](const double* x) {
    const std::uint64_t count = coordinates.size() / N + 1;
    ticker.tick(count);
    coordinates.insert(coordinates.end(), x, x + N);
    grid.insert(x, batch);
  };

  // The first point: uniform in the domain (by rejection for a ball), keyed by attempt 0, 1, ...
  for (std::uint64_t attempt = 0;; ++attempt) {
    RandomWords words{hash_combine(key, attempt)};
    double first[N];
    for (int j = 0; j < N; ++j) first[j] = box.lo + box.side * bits_to_unit(words());
    if (box.contains(first, N)) {
      add(first);
      break;
    }
  }

  // The queue holds point indices; a point is visited once per time it is queued. Candidate t of
  // visit v of point i comes from the words of (seed, i + 1, v, t) (index 0 above is the first point's).
  std::vector<std::uint32_t> queue{0};
  std::vector<std::uint32_t> visits{0};
  auto throw_candidates = [&](std::uint64_t begin, std::uint64_t end, Survivors<N>& out) {
    out.clear();
    for (std::uint64_t e = begin; e < end; ++e) {
      const std::uint32_t i = queue[e];
      const double* parent = coordinates.data() + std::size_t{i} * N;
      const std::uint64_t visit_key = hash_combine(hash_combine(key, std::uint64_t{i} + 1), visits[i]);
      for (std::uint64_t t = 0; t < k; ++t) {
        RandomWords words{hash_combine(visit_key, t)};
        double candidate[N];
        annulus_offset<N>(words, normal, r, candidate);
        for (int j = 0; j < N; ++j) candidate[j] += parent[j];
        if (!box.contains(candidate, N) || grid.conflicts(candidate)) continue;
        out.coordinates.insert(out.coordinates.end(), candidate, candidate + N);
        out.thrown_by.push_back(e * k + t);
      }
    }
  };

  std::vector<Survivors<N>> chunks;
  std::uint64_t next = 0;  // the queue's head: entries [next, queue.size()) wait
  bool stopped = max_points <= 1;
  while (!stopped && next < queue.size()) {
    ++batch;
    const std::uint64_t end = std::min<std::uint64_t>(queue.size(), next + kEntriesPerBatch);
    const std::uint64_t chunk_count = (end - next + kEntriesPerChunk - 1) / kEntriesPerChunk;
    if (chunks.size() < chunk_count) chunks.resize(chunk_count);
    // Throw and check against the points placed before the batch: only reads, in parallel.
    auto run_chunk = [&](std::uint64_t c) {
      const std::uint64_t begin = next + c * kEntriesPerChunk;
      throw_candidates(begin, std::min(end, begin + kEntriesPerChunk), chunks[c]);
    };
    if (thread_count > 1 && chunk_count > 1) {
#pragma omp parallel for num_threads(std::min<std::uint64_t>(thread_count, chunk_count)) schedule(dynamic, 1)
      for (std::int64_t c = 0; c < static_cast<std::int64_t>(chunk_count); ++c) run_chunk(static_cast<std::uint64_t>(c));
    } else {
      for (std::uint64_t c = 0; c < chunk_count; ++c) run_chunk(c);
    }
    // In the order thrown, against the points placed since the batch began. A visit that placed a
    // point queues its point again, after the points it placed; one that placed none retires it.
    std::uint64_t entry = next;
    bool entry_placed = false;
    auto finish_entries_before = [&](std::uint64_t e) {
      for (; entry < e; ++entry, entry_placed = false) {
        const std::uint32_t i = queue[entry];
        ++visits[i];
        if (entry_placed) queue.push_back(i);
      }
    };
    for (std::uint64_t c = 0; c < chunk_count && !stopped; ++c) {
      const Survivors<N>& s = chunks[c];
      for (std::size_t m = 0; m < s.thrown_by.size(); ++m) {
        finish_entries_before(s.thrown_by[m] / k);
        const double* candidate = s.coordinates.data() + m * N;
        if (grid.template conflicts<true>(candidate, batch)) continue;
        queue.push_back(static_cast<std::uint32_t>(coordinates.size() / N));
        visits.push_back(0);
        add(candidate);
        entry_placed = true;
        if (coordinates.size() / N >= max_points) {
          result.candidates_tried = s.thrown_by[m] + 1;
          stopped = true;
          break;
        }
      }
    }
    if (!stopped) finish_entries_before(end);
    next = end;
  }
  if (!stopped) result.candidates_tried = next * k;
  result.reached_max_points = stopped;
  return result;
}

PoissonDiskResult poisson_disk(int dimension, const PoissonDiskOptions& options, std::uint64_t seed, int threads,
                               const FractionProgress& progress) {
  return dispatch_dimension(dimension, [&]<int N>() { return poisson_disk<N>(options, seed, threads, progress); });
}

}  // namespace dfvn
