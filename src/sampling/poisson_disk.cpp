#include "sampling/poisson_disk.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/dimension.hpp"
#include "core/hash.hpp"

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

// Occupied grid cells of side r, keyed by their packed integer coordinates, in an open-addressing
// hash table; the points of a cell form a linked list through next_.
template <int N>
class CellGrid {
 public:
  CellGrid(const Box& domain, double radius) : lo_(domain.lo), cell_(radius), r2_(radius * radius) {
    cells_per_axis_ = static_cast<std::int64_t>(std::max(1.0, std::ceil(domain.side / radius)));
    bits_ = 1;
    while ((std::int64_t{1} << bits_) - 1 < cells_per_axis_) ++bits_;
    keys_.assign(1024, kEmpty);
    heads_.assign(1024, 0);
  }

  // True if some stored point is closer than r to x.
  bool has_point_within_radius(const double* x, const std::vector<double>& coordinates) const {
    std::int64_t cell[N];
    double below[N], above[N];
    for (int j = 0; j < N; ++j) {
      cell[j] = cell_of(x[j]);
      // Distances to the lower and upper faces of x's cell, shrunk by a hair so that rounding in
      // cell_of() can never prune a cell that holds a conflicting point.
      const double offset = x[j] - (lo_ + static_cast<double>(cell[j]) * cell_);
      below[j] = std::max(0.0, offset - 1e-12 * cell_);
      above[j] = std::max(0.0, cell_ - offset - 1e-12 * cell_);
    }
    return visit(0, 0, 0.0, cell, below, above, x, coordinates);
  }

  void insert(std::uint32_t index, const double* x) {
    if (2 * (size_ + 1) > keys_.size()) grow();
    std::uint64_t key = 0;
    for (int j = 0; j < N; ++j) key |= static_cast<std::uint64_t>(cell_of(x[j])) << (j * bits_);
    const std::size_t slot = find_slot(key);
    if (keys_[slot] == kEmpty) {
      keys_[slot] = key;
      heads_[slot] = kNone;
      ++size_;
    }
    next_.resize(std::max<std::size_t>(next_.size(), index + 1));
    next_[index] = heads_[slot];
    heads_[slot] = index;
  }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};  // cell coordinates never pack to all ones
  static constexpr std::uint32_t kNone = ~std::uint32_t{0};

  std::int64_t cell_of(double v) const {
    const auto c = static_cast<std::int64_t>(std::floor((v - lo_) / cell_));
    return std::clamp<std::int64_t>(c, 0, cells_per_axis_ - 1);
  }

  std::size_t find_slot(std::uint64_t key) const {
    const std::size_t mask = keys_.size() - 1;
    std::size_t slot = mix64(key) & mask;
    while (keys_[slot] != kEmpty && keys_[slot] != key) slot = (slot + 1) & mask;
    return slot;
  }

  void grow() {
    std::vector<std::uint64_t> old_keys(keys_.size() * 2, kEmpty);
    std::vector<std::uint32_t> old_heads(heads_.size() * 2, 0);
    old_keys.swap(keys_);
    old_heads.swap(heads_);
    for (std::size_t i = 0; i < old_keys.size(); ++i) {
      if (old_keys[i] == kEmpty) continue;
      const std::size_t slot = find_slot(old_keys[i]);
      keys_[slot] = old_keys[i];
      heads_[slot] = old_heads[i];
    }
  }

  // Depth-first over axes: offset 0, -1, +1 along `axis`, keeping the squared distance from x to the
  // cell box so far; a branch whose bound reaches r^2 cannot hold a conflicting point.
  bool visit(int axis, std::uint64_t key, double bound2, const std::int64_t* cell, const double* below,
             const double* above, const double* x, const std::vector<double>& coordinates) const {
    if (axis == N) {
      const std::size_t slot = find_slot(key);
      if (keys_[slot] == kEmpty) return false;
      for (std::uint32_t p = heads_[slot]; p != kNone; p = next_[p]) {
        const double* y = coordinates.data() + static_cast<std::size_t>(p) * N;
        double dist2 = 0.0;
        for (int j = 0; j < N; ++j) dist2 += (x[j] - y[j]) * (x[j] - y[j]);
        if (dist2 < r2_) return true;
      }
      return false;
    }
    const int shift = axis * bits_;
    if (visit(axis + 1, key | static_cast<std::uint64_t>(cell[axis]) << shift, bound2, cell, below, above, x, coordinates))
      return true;
    if (cell[axis] > 0 && bound2 + below[axis] * below[axis] < r2_ &&
        visit(axis + 1, key | static_cast<std::uint64_t>(cell[axis] - 1) << shift, bound2 + below[axis] * below[axis],
              cell, below, above, x, coordinates))
      return true;
    if (cell[axis] + 1 < cells_per_axis_ && bound2 + above[axis] * above[axis] < r2_ &&
        visit(axis + 1, key | static_cast<std::uint64_t>(cell[axis] + 1) << shift, bound2 + above[axis] * above[axis],
              cell, below, above, x, coordinates))
      return true;
    return false;
  }

  double lo_, cell_, r2_;
  std::int64_t cells_per_axis_;
  int bits_;
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> heads_;
  std::vector<std::uint32_t> next_;
  std::size_t size_ = 0;
};

}  // namespace

template <int N>
PoissonDiskResult poisson_disk(const PoissonDiskOptions& options, std::uint64_t seed, const FractionProgress& progress) {
  options.validate(N);
  const Box& box = options.domain;
  const double r = options.radius;
  const std::uint64_t max_points = std::min<std::uint64_t>(options.max_points, std::numeric_limits<std::uint32_t>::max() - 1);
  PoissonDiskResult result;
  result.points = PointSet{N, {}, box};
  std::vector<double>& coordinates = result.points.coordinates;
  CellGrid<N> grid(box, r);
  std::vector<std::uint32_t> active;
  std::uint64_t counter = 0;
  auto uniform = [&](std::uint64_t lane) { return random_unit(seed, Stream::poisson_disk, counter, lane); };
  const ProgressTicker ticker(progress, max_points);
  auto add = [&](const double* x) {
    const auto index = static_cast<std::uint32_t>(coordinates.size() / N);
    ticker.tick(index + std::uint64_t{1});
    coordinates.insert(coordinates.end(), x, x + N);
    grid.insert(index, x);
    active.push_back(index);
  };

  if (max_points == 0) return result;
  double first[N];
  for (int j = 0; j < N; ++j) first[j] = box.lo + box.side * uniform(static_cast<std::uint64_t>(j));
  ++counter;
  add(first);

  // Volume sampling of the annulus r <= |d| <= 2r: |d|^N uniform in [r^N, (2r)^N].
  const double annulus_ratio = std::pow(2.0, N) - 1.0;
  while (!active.empty() && coordinates.size() / N < max_points) {
    const auto a = static_cast<std::size_t>(uniform(0) * static_cast<double>(active.size()));
    ++counter;
    const std::uint32_t parent = active[a];
    bool placed = false;
    for (int k = 0; k < options.candidates && !placed; ++k, ++counter) {
      ++result.candidates_tried;
      double direction[N], norm2 = 0.0;
      for (int j = 0; j < N; ++j) {  // Box-Muller: a Gaussian vector has a uniform direction
        const double u1 = 1.0 - uniform(static_cast<std::uint64_t>(2 * j));
        const double u2 = uniform(static_cast<std::uint64_t>(2 * j + 1));
        direction[j] = std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
        norm2 += direction[j] * direction[j];
      }
      if (!(norm2 > 0.0)) continue;
      const double length = r * std::pow(1.0 + uniform(2 * N) * annulus_ratio, 1.0 / N) / std::sqrt(norm2);
      double candidate[N];
      const double* p = coordinates.data() + static_cast<std::size_t>(parent) * N;
      for (int j = 0; j < N; ++j) candidate[j] = p[j] + length * direction[j];
      if (!box.contains(candidate, N) || grid.has_point_within_radius(candidate, coordinates)) continue;
      add(candidate);
      placed = true;
    }
    if (!placed) {
      active[a] = active.back();
      active.pop_back();
    }
  }
  result.reached_max_points = coordinates.size() / N >= max_points;
  return result;
}

PoissonDiskResult poisson_disk(int dimension, const PoissonDiskOptions& options, std::uint64_t seed,
                               const FractionProgress& progress) {
  return dispatch_dimension(dimension, [&]<int N>() { return poisson_disk<N>(options, seed, progress); });
}

}  // namespace dfvn
