#include "dfvn/experiment/streamed_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>
#include <cerrno>
#include <sys/resource.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <fmt/format.h>

#include "dfvn/core/interval_union.hpp"
#include "dfvn/core/message_text.hpp"
#include "dfvn/core/stopwatch.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "dfvn/sampling/jitter.hpp"
#include "dfvn/stats/distance_scale.hpp"
#include "dfvn/stats/nearest_neighbour.hpp"
#include "dfvn/stats/periodic_neighbours.hpp"
#include "dfvn/stats/radial_distribution.hpp"

namespace dfvn {

namespace {

bool is_lattice(Method m) { return m == Method::cnj || m == Method::jitter; }

// A temporary file of fixed-size records in the run's TemporaryDirectory, removed with its object (and on
// signals with the directory, whose registration takes every file in it).
class TemporaryFile {
 public:
  explicit TemporaryFile(std::string path) : path_(std::move(path)) {
    file_.open(path_, std::ios::binary | std::ios::in | std::ios::out | std::ios::trunc);
    if (!file_)
      throw std::runtime_error(fmt::format("cannot create the temporary file {}: {}", quote_for_message(path_, kMaxPathEchoChars),
                                           std::strerror(errno)));
  }
  ~TemporaryFile() {
    file_.close();
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  std::fstream& stream() { return file_; }
  void check() {
    if (!file_) throw std::runtime_error(fmt::format("cannot write or read the temporary file {} (disk full?)", path_));
  }
  void write(const void* data, std::size_t bytes) {
    file_.write(static_cast<const char*>(data), static_cast<std::streamsize>(bytes));
    check();
  }
  void write_at(std::uint64_t offset, const void* data, std::size_t bytes) {
    file_.seekp(static_cast<std::streamoff>(offset));
    write(data, bytes);
  }
  void read_at(std::uint64_t offset, void* data, std::size_t bytes) {
    file_.seekg(static_cast<std::streamoff>(offset));
    file_.read(static_cast<char*>(data), static_cast<std::streamsize>(bytes));
    check();
  }
  void rewind() {
    file_.flush();
    file_.clear();
  }

 private:
  std::string path_;
  std::fstream file_;
};

// The folder of $TMPDIR (std::filesystem::temp_directory_path: $TMPDIR, else /tmp); throws naming it when
// it is no directory.
std::filesystem::path temporary_folder() {
  std::error_code error;
  std::filesystem::path folder = std::filesystem::temp_directory_path(error);
  if (error) {
    const char* tmpdir = std::getenv("TMPDIR");
    throw std::runtime_error(fmt::format("--stream keeps its temporary files in $TMPDIR, and {} is not a directory",
                                         quote_for_message(tmpdir ? tmpdir : "/tmp", kMaxPathEchoChars)));
  }
  return folder;
}

// The run's temporary directory in $TMPDIR, registered (as a tree: with every file in it) before it is
// created, so that a signal at any moment of its filling removes it whole.
class TemporaryDirectory {
 public:
  TemporaryDirectory() {
    static int serial = 0;
    path_ = (temporary_folder() / fmt::format("dfvn-stream.{}.{}", ::getpid(), serial++)).string();
    registration_ = std::make_unique<TemporaryRegistration>(path_, TemporaryRegistration::Kind::tree);
    std::error_code error;
    if (!std::filesystem::create_directory(path_, error)) {
      registration_.reset();  // not ours: leave it
      throw std::runtime_error(fmt::format("cannot create the temporary directory {}: {}",
                                           quote_for_message(path_, kMaxPathEchoChars),
                                           error ? error.message() : "it exists"));
    }
  }
  ~TemporaryDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  std::string file(const std::string& name) const { return (std::filesystem::path(path_) / name).string(); }

 private:
  std::string path_;
  std::unique_ptr<TemporaryRegistration> registration_;
};

// Sorted runs of doubles (one per slab) in one file, and exact order statistics over them by a k-way
// merge that reads each run a block at a time.
class SortedRuns {
 public:
  explicit SortedRuns(const std::string& path) : file_(path) {}
  void add(std::vector<double>& values) {
    std::sort(values.begin(), values.end());
    starts_.push_back(total_);
    file_.write(values.data(), values.size() * sizeof(double));
    total_ += values.size();
  }
  std::uint64_t size() const { return total_; }
  // The values at ascending ranks `ranks` (each < size()).
  std::vector<double> at_ranks(const std::vector<std::uint64_t>& ranks) {
    file_.rewind();
    constexpr std::uint64_t kBlock = 1 << 14;
    struct Cursor {
      std::uint64_t next, end;
      std::vector<double> block;
      std::size_t at = 0;
    };
    std::vector<Cursor> cursors;
    for (std::size_t r = 0; r < starts_.size(); ++r) {
      const std::uint64_t end = r + 1 < starts_.size() ? starts_[r + 1] : total_;
      if (end > starts_[r]) cursors.push_back({starts_[r], end, {}, 0});
    }
    auto refill = [&](Cursor& c) {
      const std::uint64_t n = std::min(kBlock, c.end - c.next);
      c.block.resize(n);
      if (n) file_.read_at(c.next * sizeof(double), c.block.data(), n * sizeof(double));
      c.next += n;
      c.at = 0;
    };
    for (Cursor& c : cursors) refill(c);
    std::vector<double> out;
    std::uint64_t rank = 0;
    for (std::uint64_t wanted : ranks) {
      for (;; ++rank) {
        Cursor* best = nullptr;
        for (Cursor& c : cursors)
          if (c.at < c.block.size() && (!best || c.block[c.at] < best->block[best->at])) best = &c;
        if (!best) throw std::logic_error("an order statistic past the values");
        const double v = best->block[best->at++];
        if (best->at == best->block.size() && best->next < best->end) refill(*best);
        if (rank == wanted) {
          out.push_back(v);
          ++rank;
          break;
        }
      }
    }
    return out;
  }

 private:
  TemporaryFile file_;
  std::vector<std::uint64_t> starts_;
  std::uint64_t total_ = 0;
};

std::function<double(std::uint64_t)> order_statistics(SortedRuns& runs) {
  // The ranks summarize_nearest_neighbours and median_of_sorted read, fetched once.
  std::vector<std::uint64_t> ranks = nearest_neighbour_summary_ranks(runs.size());
  std::vector<double> values = runs.at_ranks(ranks);
  return sorted_at_ranks(std::move(ranks), std::move(values));
}

double median_of_runs(SortedRuns& runs) {
  const std::uint64_t n = runs.size();
  if (n == 0) return 0.0;
  const std::function<double(std::uint64_t)> at = order_statistics(runs);
  return n % 2 == 1 ? at(n / 2) : 0.5 * (at(n / 2 - 1) + at(n / 2));
}

std::uint64_t layer_size(const SampleConfig& config) {
  std::uint64_t layer = 1;
  for (int a = 0; a + 1 < config.dimension; ++a) layer *= static_cast<std::uint64_t>(config.grid);
  return layer;
}

// One method's slabs: index ranges [first(s), first(s + 1)).
struct Slabs {
  std::uint64_t total = 0;
  std::uint64_t rows = 0;  // per slab (the last may hold fewer)
  int count = 0;
  std::uint64_t first(int s) const { return std::min(total, rows * static_cast<std::uint64_t>(s)); }
};

Slabs slabs_of(const SampleConfig& config, const MethodPlan& plan, int count) {
  Slabs s;
  s.total = plan.requested;
  s.count = count;
  s.rows = is_lattice(plan.method) ? layer_size(config) * static_cast<std::uint64_t>(config.grid / count)
                                   : (plan.requested + count - 1) / count;
  return s;
}

// The displacement sums of a lattice method, fed slab by slab in index order.
class DisplacementStream {
 public:
  DisplacementStream(const SampleConfig& config, double spacing, const std::string& runs_path)
      : n_(config.dimension), grid_(config.grid), layer_(layer_size(config)), spacing_(spacing), lengths_(runs_path) {
    sums_.pair_sum2.assign(static_cast<std::size_t>(n_), 0.0);
    sums_.bragg.assign(static_cast<std::size_t>(n_), 0.0);
  }
  // u: rows x N for lattice rows first .. first + rows - 1 (whole layers).
  void add(const std::vector<double>& u, std::uint64_t first) {
    const std::uint64_t rows = u.size() / static_cast<std::size_t>(n_);
    const auto at = [&](std::uint64_t r) { return u.data() + r * n_; };
    std::vector<double> lengths;
    lengths.reserve(rows);
    for (std::uint64_t r = 0; r < rows; ++r) {
      double r2 = 0.0;
      for (int a = 0; a < n_; ++a) r2 += at(r)[a] * at(r)[a];
      sums_.sum2 += r2;
      lengths.push_back(std::sqrt(r2));
      sums_.unmoved += lengths.back() < 0.01 * spacing_;
    }
    sums_.points += rows;
    sums_.included += rows;
    lengths_.add(lengths);
    // Pairs along the axes within a layer: i and i + stride_a while coordinate a of i is below K - 1.
    std::uint64_t stride = 1;
    for (int a = 0; a + 1 < n_; ++a) {
      double& sum = sums_.pair_sum2[static_cast<std::size_t>(a)];
      for (std::uint64_t r = 0; r < rows; ++r) {
        if (((first + r) / stride) % static_cast<std::uint64_t>(grid_) == static_cast<std::uint64_t>(grid_ - 1)) continue;
        add_squared_difference(sum, at(r), at(r + stride));
        ++sums_.pairs;
      }
      stride *= static_cast<std::uint64_t>(grid_);
    }
    // Along the last axis: the previous slab's last layer with this slab's first, then within the slab.
    double& last = sums_.pair_sum2[static_cast<std::size_t>(n_ - 1)];
    if (!previous_layer_.empty())
      for (std::uint64_t r = 0; r < layer_; ++r) {
        add_squared_difference(last, previous_layer_.data() + r * n_, at(r));
        ++sums_.pairs;
      }
    for (std::uint64_t r = 0; r + layer_ < rows; ++r) {
      add_squared_difference(last, at(r), at(r + layer_));
      ++sums_.pairs;
    }
    previous_layer_.assign(u.end() - static_cast<std::ptrdiff_t>(layer_ * n_), u.end());
    for (int a = 0; a < n_; ++a)
      for (std::uint64_t r = 0; r < rows; ++r)
        sums_.bragg[static_cast<std::size_t>(a)] += std::polar(1.0, 2.0 * std::numbers::pi * at(r)[a] / spacing_);
  }
  LatticeDisplacementSummary finish() { return finish_lattice_displacements(n_, spacing_, sums_, median_of_runs(lengths_)); }

 private:
  // Each coordinate's square added to the axis' sum, as summarize_lattice_displacements adds them.
  void add_squared_difference(double& sum, const double* a, const double* b) const {
    for (int k = 0; k < n_; ++k) sum += (a[k] - b[k]) * (a[k] - b[k]);
  }
  int n_, grid_;
  std::uint64_t layer_;
  double spacing_;
  LatticeDisplacementSums sums_;
  SortedRuns lengths_;
  std::vector<double> previous_layer_;
};

// The points of a set spilled by their last coordinate into buckets, then measured bucket by bucket.
class NearestStream {
 public:
  NearestStream(const SampleConfig& config, const TemporaryDirectory& dir, int buckets, const Domain& domain)
      : config_(config), n_(config.dimension), periodic_(domain.periodic()), domain_(domain),
        runs_(dir.file("distance_runs")) {
    for (int b = 0; b < buckets; ++b) {
      buckets_.push_back(std::make_unique<TemporaryFile>(dir.file(fmt::format("bucket{}", b))));
      pairs_.push_back(std::make_unique<TemporaryFile>(dir.file(fmt::format("distances{}", b))));
    }
    counts_.assign(static_cast<std::size_t>(buckets), 0);
    measured_.assign(static_cast<std::size_t>(buckets), 0);
  }
  int bucket_of(double z) const {
    const double f = (z - domain_.lo) / domain_.side * static_cast<double>(buckets_.size());
    if (!(f >= 0.0)) return 0;
    return static_cast<int>(std::min(std::floor(f), static_cast<double>(buckets_.size() - 1)));
  }
  double edge(int b) const { return domain_.lo + domain_.side * static_cast<double>(b) / static_cast<double>(buckets_.size()); }
  // Points of the output's rows first .. first + size - 1.
  void add(const PointSet& points, std::uint64_t first) {
    std::vector<std::vector<double>> records(buckets_.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double* x = points.point(i);
      const double z = x[n_ - 1];
      zmin_ = std::min(zmin_, z);
      zmax_ = std::max(zmax_, z);
      const int b = bucket_of(z);
      std::vector<double>& r = records[static_cast<std::size_t>(b)];
      const std::uint64_t index = first + i;
      double tag;
      std::memcpy(&tag, &index, sizeof tag);
      r.push_back(tag);
      r.insert(r.end(), x, x + n_);
      ++counts_[static_cast<std::size_t>(b)];
    }
    for (std::size_t b = 0; b < buckets_.size(); ++b)
      if (!records[b].empty()) buckets_[b]->write(records[b].data(), records[b].size() * sizeof(double));
    total_ += points.size();
  }
  std::uint64_t size() const { return total_; }
  // Every point's distance to its nearest other point, into the distances file by index.
  void measure(const FractionProgress& progress) {
    for (auto& b : buckets_) b->rewind();
    const double mean_spacing = domain_.side / std::pow(static_cast<double>(total_), 1.0 / n_);
    for (int b = 0; b < static_cast<int>(buckets_.size()); ++b) {
      if (counts_[static_cast<std::size_t>(b)] == 0) continue;
      measure_bucket(b, mean_spacing);
      if (progress) progress(static_cast<double>(b + 1) / static_cast<double>(buckets_.size()));
    }
  }
  // The summary: the sum in index order, the order statistics over sorted runs of `run_rows` rows.
  NearestNeighbourSummary summarize(std::uint64_t run_rows) {
    // Each bucket's (index, distance) pairs are sorted by index: a cursor per bucket fills the rows of
    // one run at a time.
    struct Cursor {
      std::uint64_t read = 0;
      std::vector<double> block;  // pairs: index bits, distance
      std::size_t at = 0;
    };
    std::vector<Cursor> cursors(buckets_.size());
    for (auto& p : pairs_) p->rewind();
    double sum = 0.0;
    std::vector<double> run;
    for (std::uint64_t first = 0; first < total_; first += run_rows) {
      const std::uint64_t end = std::min(total_, first + run_rows);
      run.assign(static_cast<std::size_t>(end - first), std::numeric_limits<double>::quiet_NaN());
      for (std::size_t b = 0; b < buckets_.size(); ++b) {
        Cursor& c = cursors[b];
        for (;;) {
          if (c.at == c.block.size()) {
            const std::uint64_t n = std::min<std::uint64_t>(1 << 14, measured_[b] - c.read);
            if (n == 0) break;
            c.block.resize(2 * n);
            pairs_[b]->read_at(2 * c.read * sizeof(double), c.block.data(), c.block.size() * sizeof(double));
            c.read += n;
            c.at = 0;
          }
          std::uint64_t i;
          std::memcpy(&i, &c.block[c.at], sizeof i);
          if (i >= end) break;
          run[static_cast<std::size_t>(i - first)] = c.block[c.at + 1];
          c.at += 2;
        }
      }
      for (double d : run) sum += d;  // in index order, as summarize_nearest_neighbours
      runs_.add(run);
    }
    if (std::isnan(sum)) throw std::logic_error("a streamed point without its nearest-neighbour distance");
    return summarize_nearest_neighbours(total_, sum, order_statistics(runs_), domain_.measure(n_), n_);
  }

  // The RDF of the whole set (after measure): each bucket's query points (RdfQueries, chosen by output
  // row as in memory) counted against the bucket and a halo a little wider than r_max, which holds every
  // point within r_max of them (around the torus when periodic_: the halo wraps, over as many buckets as
  // r_max spans). The pair sums are exact, so the curve is the in-memory run's to the bit.
  RdfCurve radial_distribution(const RdfOptions& options, std::uint64_t seed, const FractionProgress& progress) {
    const RdfPlan plan = plan_radial_distribution(n_, domain_, total_, options);
    const RdfQueries is_query(options, seed, total_);
    RdfPairSums sums = plan.empty_sums();
    std::uint64_t queries = 0;
    const double halo = plan.r_max * (1.0 + 1e-6) + 1e-9 * domain_.side;
    for (auto& b : buckets_) b->rewind();
    for (int b = 0; b < static_cast<int>(buckets_.size()); ++b) {
      if (counts_[static_cast<std::size_t>(b)] == 0) continue;
      const LoadedBucket l = load_bucket(b, halo);
      if (l.set.size() > std::numeric_limits<std::uint32_t>::max())  // more slabs help only when the slab is the bulk of it
        throw std::invalid_argument(fmt::format(
            "--stream: slab {} with its RDF halo holds {} points, more than the RDF's 2^32 - 1: lower --rdf-max{}", b + 1,
            l.set.size(), 2 * l.queries > l.set.size() ? " or raise --slabs" : ""));
      std::vector<std::uint32_t> rows;
      for (std::uint64_t q = 0; q < l.queries; ++q)
        if (is_query(l.index[q])) rows.push_back(static_cast<std::uint32_t>(q));
      if (!rows.empty()) count_rdf_pairs(l.set, rows, plan, sums, config_.threads);
      queries += rows.size();
      if (progress) progress(static_cast<double>(b + 1) / static_cast<double>(buckets_.size()));
    }
    return finish_radial_distribution(plan, sums, queries);
  }

 private:
  // Bucket b's points (rows 0 .. queries - 1 of set, in file order) and every other point whose last
  // coordinate lies in [lo, hi) = [edge(b) - h, edge(b + 1) + h), on the torus (periodic_) also shifted by
  // a side: the halo wraps, and the first and last buckets are neighbours. `whole`: every point of the set
  // is loaded (then the halo has no edge).
  struct LoadedBucket {
    PointSet set;
    std::vector<std::uint64_t> index;  // the output's row of each of set's rows
    std::uint64_t queries = 0;
    double lo = 0.0, hi = 0.0;
    bool whole_below = false, whole_above = false;  // no point lies below lo / at or above hi unloaded
    bool wraps_whole = false;                       // periodic_ and [lo, hi) covers the torus
  };
  // Whether a point of last coordinate z lies in [lo, hi) (on the torus, z or z -+ side); `wraps_whole`:
  // the range covers the whole torus.
  bool in_range(double z, double lo, double hi, bool wraps_whole) const {
    if (wraps_whole || (z >= lo && z < hi)) return true;
    const double side = domain_.side;
    return periodic_ && ((z + side >= lo && z + side < hi) || (z - side >= lo && z - side < hi));
  }
  // The records of bucket c, a block at a time: take(record) for each (index bits, then N coordinates).
  template <typename Take>
  void read_bucket(int c, Take take) {
    const std::size_t record = static_cast<std::size_t>(n_) + 1;
    constexpr std::uint64_t kRecords = 1 << 15;
    std::vector<double> block;
    const std::uint64_t count = counts_[static_cast<std::size_t>(c)];
    for (std::uint64_t first = 0; first < count; first += kRecords) {
      const std::uint64_t n = std::min(kRecords, count - first);
      block.resize(n * record);
      buckets_[static_cast<std::size_t>(c)]->read_at(first * record * sizeof(double), block.data(), block.size() * sizeof(double));
      for (std::uint64_t k = 0; k < n; ++k) take(block.data() + k * record);
    }
  }
  LoadedBucket load_bucket(int b, double h) {
    LoadedBucket l;
    l.lo = edge(b) - h;
    l.hi = edge(b + 1) + h;
    l.wraps_whole = periodic_ && l.hi - l.lo >= domain_.side;
    l.whole_below = l.wraps_whole || (!periodic_ && l.lo <= zmin_);
    l.whole_above = l.wraps_whole || (!periodic_ && l.hi > zmax_);
    l.set = PointSet{n_, {}, domain_};
    auto load = [&](int c, bool everything) {
      read_bucket(c, [&](const double* r) {
        if (!everything && !in_range(r[n_], l.lo, l.hi, l.wraps_whole)) return;
        std::uint64_t i;
        std::memcpy(&i, r, sizeof i);
        l.index.push_back(i);
        l.set.coordinates.insert(l.set.coordinates.end(), r + 1, r + 1 + n_);
      });
    };
    // The buckets within reach of b (around the torus when periodic_), each once.
    const int count = static_cast<int>(buckets_.size());
    const double width = domain_.side / static_cast<double>(count);
    const int reach = static_cast<int>(std::min<double>(count, std::ceil(h / width) + 1.0));
    std::vector<char> near(static_cast<std::size_t>(count), 0);
    for (int d = 1; d <= reach; ++d)
      for (int c : {b - d, b + d}) {
        if (periodic_) c = ((c % count) + count) % count;
        if (c >= 0 && c < count && c != b) near[static_cast<std::size_t>(c)] = 1;
      }
    std::uint64_t expected = counts_[static_cast<std::size_t>(b)];
    const double halo_share = std::min(1.0, h / width);
    for (int c = 0; c < count; ++c)
      if (near[static_cast<std::size_t>(c)])
        expected += static_cast<std::uint64_t>(std::min(1.0, halo_share / 2.0) * static_cast<double>(counts_[static_cast<std::size_t>(c)]));
    l.set.coordinates.reserve(expected * static_cast<std::uint64_t>(n_));
    l.index.reserve(expected);
    load(b, true);
    l.queries = l.index.size();
    for (int c = 0; c < count; ++c)
      if (near[static_cast<std::size_t>(c)]) load(c, false);
    return l;
  }

  // Loads bucket b (its points first) and every point within h of it, measures bucket b's points against
  // them all (the tree over every loaded point, only the bucket's points queried), and writes their
  // distances. A distance no farther than the point's margin to the loaded region's edge is certainly the
  // nearest. For the others (the few near the edges whose neighbour may lie beyond the halo) the distance
  // found is an upper bound on the true one, so the true neighbour lies within that distance of them in
  // the last coordinate: the points not loaded within those windows are read and the unsure points
  // measured again against them alone, keeping the smaller distance. Every distance is distance_between's
  // (on the torus periodic_distance_between's) of the nearest point, so it is the in-memory run's bits:
  // the minimum over a set that holds the nearest point.
  void measure_bucket(int b, double h) {
    LoadedBucket l = load_bucket(b, h);
    while (l.set.size() < 2) {  // one point and an empty halo: widen it until it holds another
      if (l.whole_below && l.whole_above) throw std::invalid_argument("the statistics need at least 2 points");
      h *= 2.0;
      l = load_bucket(b, h);
    }
    const std::uint64_t queries = l.queries;
    std::vector<double> d = periodic_ ? periodic_nearest_neighbour_distances_of_first(l.set, queries, config_.threads)
                                      : nearest_neighbour_distances_of_first(l.set, queries, config_.knn, config_.threads);
    // The margins carry a relative slack far above the rounding of an edge and a difference.
    constexpr double kSlack = 1e-9;
    const double width = l.hi - l.lo;
    std::vector<std::uint64_t> unsure;
    for (std::uint64_t q = 0; q < queries; ++q) {
      // A point outside [lo, hi) (and, on the torus, its images) is at least this far from the query in
      // its last coordinate.
      const double z = l.set.point(q)[n_ - 1];
      const double margin = std::min(l.whole_below ? std::numeric_limits<double>::infinity() : z - l.lo,
                                     l.whole_above ? std::numeric_limits<double>::infinity() : l.hi - z);
      if (!(d[q] <= margin - kSlack * width)) unsure.push_back(q);
    }
    if (!unsure.empty()) remeasure(b, l, unsure, d);
    std::vector<std::pair<std::uint64_t, double>> pairs(queries);
    for (std::uint64_t q = 0; q < queries; ++q) pairs[q] = {l.index[q], d[q]};
    std::sort(pairs.begin(), pairs.end());
    std::vector<double> out(2 * queries);
    for (std::uint64_t q = 0; q < queries; ++q) {
      std::memcpy(&out[2 * q], &pairs[q].first, sizeof(double));
      out[2 * q + 1] = pairs[q].second;
    }
    pairs_[static_cast<std::size_t>(b)]->write(out.data(), out.size() * sizeof(double));
    measured_[static_cast<std::size_t>(b)] = queries;
  }

  // The unsure points of bucket b (rows `unsure` of l.set, with their distances d over l.set): each against
  // the points that l did not load and whose last coordinate lies within d (and a slack) of its own, on the
  // torus around it. d[q] becomes the smaller of the two distances.
  void remeasure(int b, const LoadedBucket& l, const std::vector<std::uint64_t>& unsure, std::vector<double>& d) {
    const double side = domain_.side;
    std::vector<IntervalUnion::Interval> reaches;
    for (std::uint64_t q : unsure) {
      const double z = l.set.point(q)[n_ - 1], reach = d[q] * (1.0 + 1e-6) + 1e-9 * side;
      reaches.emplace_back(z - reach, z + reach);
    }
    const IntervalUnion windows(std::move(reaches));
    const auto& merged = windows.intervals();
    const auto near = [&](double z) {
      return windows.contains(z) || (periodic_ && (windows.contains(z - side) || windows.contains(z + side)));
    };
    // The set: the unsure points first, then the candidates from the other buckets (bucket b is loaded
    // whole). A bucket is read if its range, widened by a slack (its first and last take every point below
    // and above the box), meets a window.
    PointSet set{n_, {}, domain_};
    for (std::uint64_t q : unsure) set.coordinates.insert(set.coordinates.end(), l.set.point(q), l.set.point(q) + n_);
    const int count = static_cast<int>(buckets_.size());
    const double slack = 1e-9 * side;
    for (int c = 0; c < count; ++c) {
      if (c == b || counts_[static_cast<std::size_t>(c)] == 0) continue;
      const double lo = c == 0 ? -std::numeric_limits<double>::infinity() : edge(c) - slack;
      const double hi = c == count - 1 ? std::numeric_limits<double>::infinity() : edge(c + 1) + slack;
      bool meets = false;
      for (double shift : {0.0, -side, side}) {
        if (shift != 0.0 && !periodic_) continue;
        for (const auto& w : merged) meets = meets || (w.first + shift <= hi && w.second + shift >= lo);
      }
      if (!meets) continue;
      read_bucket(c, [&](const double* r) {
        const double z = r[n_];
        if (!in_range(z, l.lo, l.hi, l.wraps_whole) && near(z)) set.coordinates.insert(set.coordinates.end(), r + 1, r + 1 + n_);
      });
    }
    if (set.size() == unsure.size()) return;  // nothing beyond the halo within reach: the distances stand
    const std::vector<double> again = periodic_ ? periodic_nearest_neighbour_distances_of_first(set, unsure.size(), config_.threads)
                                                : nearest_neighbour_distances_of_first(set, unsure.size(), config_.knn, config_.threads);
    for (std::size_t j = 0; j < unsure.size(); ++j) d[unsure[j]] = std::min(d[unsure[j]], again[j]);
  }

  const SampleConfig& config_;
  int n_;
  bool periodic_;
  Domain domain_;
  std::vector<std::unique_ptr<TemporaryFile>> buckets_;
  std::vector<std::uint64_t> counts_;
  std::vector<std::unique_ptr<TemporaryFile>> pairs_;  // per bucket: its points' (index, distance), by index
  std::vector<std::uint64_t> measured_;
  SortedRuns runs_;
  std::uint64_t total_ = 0;
  double zmin_ = std::numeric_limits<double>::infinity(), zmax_ = -std::numeric_limits<double>::infinity();
};

MethodResult run_streamed_method(const SampleConfig& config, const MethodPlan& plan, int slab_count,
                                 const std::function<std::string(Method)>& point_path, PointFormat format,
                                 const StageProgress& progress) {
  const std::string name(to_string(plan.method));
  MethodResult result;
  result.plan = plan;
  const Slabs slabs = slabs_of(config, plan, slab_count);
  TemporaryDirectory dir;
  const bool lattice_method = is_lattice(plan.method);
  const LatticeSpec lattice = config.lattice();
  const double spacing = plan.method == Method::cnj ? cnj_lattice(lattice, config.cnj.domain).spacing() : lattice.spacing();
  std::unique_ptr<DisplacementStream> displacement;
  if (lattice_method) displacement = std::make_unique<DisplacementStream>(config, spacing, dir.file("length_runs"));
  std::unique_ptr<NearestStream> nearest;
  const Domain domain = plan.domain;
  if (config.compute_statistics) {
    if (domain_scale(domain.side) != 1.0) throw std::invalid_argument("--stream measures sets of ordinary side only");
    nearest = std::make_unique<NearestStream>(config, dir, slab_count, domain);
  }
  // The count is known up front unless drop mode drops points.
  const bool count_known = !(plan.method == Method::cnj && config.cnj.domain_mode == DomainMode::drop);
  std::unique_ptr<PointFileWriter> writer;
  if (point_path) writer = std::make_unique<PointFileWriter>(point_path(plan.method), format, config.dimension, plan.requested, count_known);

  if (progress) progress(name, 0.0);
  Stopwatch stopwatch;
  std::uint64_t accepted = 0, dropped = 0, skipped = 0, retraced = 0, kept = 0;
  double trace_time = 0.0, field_frequency = 0.0;
  for (int s = 0; s < slabs.count; ++s) {
    const std::uint64_t first = slabs.first(s), rows = slabs.first(s + 1) - first;
    if (rows == 0) continue;
    Slab slab = generate_slab(config, plan, first, rows);
    if (writer) writer->append(slab.points.coordinates.data(), slab.points.size());
    if (displacement) displacement->add(slab.displacements, first);
    if (nearest) nearest->add(slab.points, accepted);
    accepted += slab.points.size();
    dropped += slab.dropped;
    skipped += slab.skipped;
    retraced += slab.retraced;
    kept += slab.kept;
    trace_time = slab.trace_time;
    field_frequency = slab.field_frequency;
    if (progress) progress(name, static_cast<double>(s + 1) / slabs.count);
  }
  result.point_count = accepted;
  GenerationFacts& facts = result.facts;
  if (plan.method == Method::cnj) {
    facts.frequency = config.cnj.frequency;
    facts.field_frequency = field_frequency;
    facts.trace_time = trace_time;
    facts.dropped = dropped;
    facts.skipped_updates = skipped;
    facts.retraced = retraced;
    facts.kept_at_site = kept;
    result.notes = fmt::format("{} noise; {}", to_string(config.cnj.noise), to_string(config.cnj.domain_mode));
    if (config.cnj.field == FieldKind::curl) result.notes += "; curl noise field, no reprojection";
  } else if (plan.method == Method::jitter) {
    facts.half_width = jitter_half_width(lattice);
  } else if (plan.method == Method::sobol) {
    result.notes = fmt::format("{} scrambling", to_string(config.scramble));
  }
  if (displacement) result.displacement = displacement->finish();
  result.seconds_generate = stopwatch.seconds();
  // As in memory: a set too small to measure is an error before its point file is written.
  if (nearest && accepted < 2)
    throw std::invalid_argument(fmt::format("the {} point set has {} point(s) ({}); the statistics need at least 2", name,
                                            accepted, facts.dropped ? fmt::format("{} dropped", *facts.dropped) : result.notes));
  if (writer) writer->commit();
  if (!nearest) return result;
  const std::string stage = name + " statistics";
  if (progress) progress(stage, 0.0);
  stopwatch.restart();
  nearest->measure([&](double f) {
    if (progress) progress(stage, f);
  });
  result.nearest = nearest->summarize(slabs.rows);
  result.measured = true;
  result.seconds_stats = stopwatch.seconds();
  if (config.compute_rdf) {
    const std::string rdf_stage = name + " rdf";
    if (progress) progress(rdf_stage, 0.0);
    result.rdf = nearest->radial_distribution(config.rdf, config.seed, [&](double f) {
      if (progress) progress(rdf_stage, f);
    });
  }
  return result;
}

}  // namespace

namespace {

Slab generate_slab_points(const SampleConfig& config, const MethodPlan& plan, std::uint64_t first, std::uint64_t rows) {
  const LatticeSpec lattice = config.lattice();
  Slab s;
  if (rows == 0) {
    s.points = PointSet{config.dimension, {}, plan.domain};
    return s;
  }
  switch (plan.method) {
    case Method::cnj: {
      CnjResult r = curl_noise_jitter_range(lattice, config.cnj, config.seed, first, rows, config.threads);
      s.points = std::move(r.points);
      s.displacements = std::move(r.displacements);
      s.dropped = r.dropped;
      s.skipped = r.trace_stats.skipped_updates;
      s.retraced = r.retraced;
      s.kept = r.kept_at_site;
      s.trace_time = r.trace_time;
      s.field_frequency = r.field_frequency;
      return s;
    }
    case Method::jitter: {
      s.points = jittered_lattice_range(lattice, jitter_half_width(lattice), first, rows, config.seed, config.threads);
      const int n = config.dimension;
      s.displacements.resize(s.points.coordinates.size());
      std::vector<double> site(static_cast<std::size_t>(n));
      for (std::uint64_t r = 0; r < rows; ++r) {
        lattice.point(first + r, site.data());
        for (int a = 0; a < n; ++a) s.displacements[r * n + a] = s.points.point(r)[a] - site[a];
      }
      return s;
    }
    case Method::random:
      s.points = uniform_random_points_range(config.dimension, first, rows, plan.domain.box(), config.seed, config.threads);
      return s;
    case Method::sobol:
      s.points = sobol_points_range(config.dimension, first, rows, plan.domain.box(), config.scramble, config.seed, config.threads);
      return s;
    default: break;
  }
  throw std::logic_error("a method that does not stream");
}

}  // namespace

Slab generate_slab(const SampleConfig& config, const MethodPlan& plan, std::uint64_t first, std::uint64_t rows) {
  Slab s = generate_slab_points(config, plan, first, rows);
  s.points.domain = plan.domain;  // as run_sampling's sets: where the plan says they live
  return s;
}

std::string stream_refusal(const SampleConfig& config) {
  if (config.domain() == DomainKind::sphere || config.domain() == DomainKind::ball)
    return fmt::format("--stream cuts the K^N lattice of a torus or cube into slabs, not --domain {}",
                       to_string(config.domain()));
  for (Method m : config.methods) {
    if (m == Method::pds || m == Method::jitter_matched || m == Method::halton || m == Method::lhs)
      return fmt::format("--stream makes the index-addressable sets cnj, jitter, random and sobol in slabs, not {}{}",
                         to_string(m),
                         m == Method::pds ? " (Poisson disk places each point after all before it)" : "");
  }
  return {};
}

int stream_slab_count(const SampleConfig& config, int requested) {
  const bool lattice = std::any_of(config.methods.begin(), config.methods.end(), is_lattice);
  std::uint64_t fewest_points = std::numeric_limits<std::uint64_t>::max();
  for (Method m : config.methods) fewest_points = std::min(fewest_points, plan_method(config, m).requested);
  if (requested > 0) {
    if (lattice && config.grid % requested != 0)
      throw std::invalid_argument(fmt::format("--slabs {} does not divide --grid {}: a slab holds whole layers of the "
                                              "lattice (divisors of {})",
                                              requested, config.grid, config.grid));
    if (static_cast<std::uint64_t>(requested) > fewest_points)
      throw std::invalid_argument(fmt::format("--slabs {} is more slabs than points ({})", requested, fewest_points));
    return requested;
  }
  std::uint64_t most_points = 0;
  for (Method m : config.methods) most_points = std::max(most_points, plan_method(config, m).requested);
  // The fewest slabs of at most kStreamSlabPoints points whose peak fits the memory limit (else the most).
  const double limit = memory_limit_bytes(config);
  const auto fits = [&](int s) {
    return most_points / static_cast<std::uint64_t>(s) <= kStreamSlabPoints && streamed_peak_bytes(config, s) <= limit;
  };
  if (lattice) {
    for (int s = 1; s <= config.grid; ++s)
      if (config.grid % s == 0 && fits(s)) return s;
    return config.grid;
  }
  const int most = static_cast<int>(std::min<std::uint64_t>(fewest_points, 1 << 20));
  for (int s = 1; s < most; s *= 2)
    if (fits(s)) return s;
  return most;
}

double streamed_peak_bytes(const SampleConfig& config, int slabs) {
  double peak = 0.0;
  for (Method m : config.methods) {
    const MethodPlan plan = plan_method(config, m);
    const double total = static_cast<double>(plan.requested), points = total / slabs;
    // A bucket and a halo of about a layer each side, with the KD-tree's copy and the slab being written;
    // the RDF's halo reaches r_max (by default 2.5 mean spacings) each side.
    double halo = 2.0 * static_cast<double>(layer_size(config));
    if (config.compute_rdf && config.compute_statistics) {
      const double r = config.rdf.r_max > 0.0 ? config.rdf.r_max / plan.domain.side : 2.5 / std::pow(total, 1.0 / config.dimension);
      halo = std::max(halo, 2.0 * std::min(1.0, r) * total);
    }
    peak = std::max(peak, std::min(points + halo, total) * (16.0 * config.dimension + 48.0));
  }
  return peak;
}

double streamed_temporary_bytes(const SampleConfig& config) {
  double peak = 0.0;
  for (Method m : config.methods) {
    const double points = static_cast<double>(plan_method(config, m).requested);
    // Per point: the lattice methods' displacement lengths (one double, SortedRuns); with statistics its
    // bucket record (index and N coordinates), its (index, distance) pair and the sorted distance.
    double per_point = is_lattice(m) ? 8.0 : 0.0;
    if (config.compute_statistics) per_point += 8.0 * (config.dimension + 1) + 16.0 + 8.0;
    peak = std::max(peak, points * per_point);  // each method's folder is removed before the next starts
  }
  return peak;
}

std::string stream_temporaries_refusal(const SampleConfig& config, int slabs) {
  const std::filesystem::path folder = temporary_folder();
  const std::string where = quote_for_message(folder.string(), kMaxPathEchoChars);
  struct statvfs space {};
  if (::statvfs(folder.c_str(), &space) != 0)
    return fmt::format("--stream keeps its temporary files in $TMPDIR {}, which cannot be examined: {}", where,
                       std::strerror(errno));
  const double needed = streamed_temporary_bytes(config);
  const double free_bytes = static_cast<double>(space.f_bavail) * static_cast<double>(space.f_frsize);
  if (needed > free_bytes)
    return fmt::format("--stream needs about {} of temporary files in $TMPDIR {}, which has {} free: point TMPDIR at a "
                       "larger file system, or make fewer points",
                       byte_size(needed), where, byte_size(free_bytes));
  // Every bucket keeps two files open (its records and its distances), besides the sorted distances, the
  // displacement lengths, the point file and the program's own (standard streams, libraries): 16.
  struct rlimit files {};
  if (config.compute_statistics && ::getrlimit(RLIMIT_NOFILE, &files) == 0 && files.rlim_cur != RLIM_INFINITY) {
    const std::uint64_t open = 2 * static_cast<std::uint64_t>(slabs) + 16;
    if (open > files.rlim_cur)
      return fmt::format("--stream in {} slabs keeps about {} temporary files open at once, more than this process may "
                         "open ({}, ulimit -n): {}",
                         slabs, open, static_cast<std::uint64_t>(files.rlim_cur),
                         config.stream_slabs > 0 ? "give fewer --slabs, or raise the limit" : "raise the limit");
  }
  return {};
}

std::string streamed_memory_advice(const SampleConfig& config, int slabs, double limit) {
  // The slab counts a run may take (stream_slab_count's): the divisors of K for the lattice methods, else
  // up to the fewest points (the automatic count tries powers of two up to 2^20 and then that).
  const bool lattice = std::any_of(config.methods.begin(), config.methods.end(), is_lattice);
  std::uint64_t fewest_points = std::numeric_limits<std::uint64_t>::max();
  for (Method m : config.methods) fewest_points = std::min(fewest_points, plan_method(config, m).requested);
  std::vector<int> counts;
  if (lattice) {
    for (int s = slabs + 1; s <= config.grid; ++s)
      if (config.grid % s == 0) counts.push_back(s);
  } else {
    const auto most = static_cast<int>(std::min<std::uint64_t>(fewest_points, std::uint64_t{1} << 30));
    for (long long s = 2LL * slabs; s < most; s *= 2) counts.push_back(static_cast<int>(s));
    if (most > slabs) counts.push_back(most);
  }
  const auto fits_with_more_slabs = [&](const SampleConfig& c) {
    return std::any_of(counts.begin(), counts.end(), [&](int s) { return streamed_peak_bytes(c, s) <= limit; });
  };
  if (fits_with_more_slabs(config)) return "raise --slabs or --max-memory GIB";
  if (config.compute_rdf && config.compute_statistics) {
    // The RDF's halo (r_max each side, over as many slabs as it spans) is what does not fit when the run
    // without it would fit with these slabs or more.
    SampleConfig without = config;
    without.compute_rdf = false;
    if (streamed_peak_bytes(without, slabs) <= limit || fits_with_more_slabs(without))
      return "lower --rdf-max or raise --max-memory GIB";
  }
  return lattice && slabs == config.grid ? "raise --max-memory GIB (a slab is one layer of the lattice already)"
                                          : "raise --max-memory GIB (more slabs would not fit either)";
}

std::vector<MethodResult> run_streamed_sampling(const SampleConfig& config, int slabs,
                                                const std::function<std::string(Method)>& point_path,
                                                PointFormat format, const StageProgress& progress) {
  config.validate();
  if (const std::string why = stream_refusal(config); !why.empty()) throw std::invalid_argument(why);
  const int count = stream_slab_count(config, slabs);
  if (const std::string why = stream_temporaries_refusal(config, count); !why.empty()) throw std::invalid_argument(why);
  std::vector<MethodResult> results;
  for (Method m : config.methods)
    results.push_back(run_streamed_method(config, plan_method(config, m), count, point_path, format, progress));
  return results;
}

}  // namespace dfvn
