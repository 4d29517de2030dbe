#include "dfvn/stats/radial_distribution.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <type_traits>

#include <fmt/format.h>

#include "dfvn/core/dimension.hpp"
#include "dfvn/core/hash.hpp"
#include "dfvn/core/parallel.hpp"
#include "dfvn/core/simd.hpp"
#include "dfvn/stats/distance_scale.hpp"
#include "dfvn/stats/kd_tree.hpp"
#include "dfvn/stats/nearest_other.hpp"
#include "dfvn/stats/periodic_images.hpp"
#include "dfvn/stats/periodic_neighbours.hpp"

namespace dfvn {

void RdfOptions::validate() const {
  if (!std::isfinite(r_max) || r_max < 0.0) throw std::invalid_argument("RDF r_max must be a finite number >= 0");
  if (bins < 1 || bins > 100000) throw std::invalid_argument("RDF bins must be in 1..100000");
}

void check_rdf_resolution(int dimension, double side, double r_max, int bins) {
  // Each pair weight is at most 1 / (L - r_max)^N, since the overlap of the cube with its translate
  // by d is prod_a (L - |d_a|) and |d_a| <= r_max; with at most q (n - 1) pairs, which the
  // normalisation V^2 / (q (n - 1)) divides out, g_k <= V^2 / ((L - r_max)^N shell_k). The first
  // shell, ball * width^N, is the narrowest. In base-2 logarithms, so the check cannot overflow.
  const double width = r_max / bins;
  const double log2_bound = 2.0 * dimension * std::log2(side) - dimension * std::log2(side - r_max) -
                            std::log2(unit_ball_volume(dimension)) - dimension * std::log2(width);
  // 2^1000 leaves room below DBL_MAX (about 2^1024) for the sums; the shell must not be subnormal.
  const double shell = unit_ball_volume(dimension) * std::pow(width, dimension);
  if (!(width > 0.0) || !(log2_bound < 1000.0) || !(shell >= std::numeric_limits<double>::min()))
    throw std::invalid_argument(fmt::format(
        "RDF r_max {:g} with {} bins gives bins {:.3g} wide, too narrow for a finite g(r) in {}D (the shell volumes "
        "underflow); raise r_max or use fewer bins",
        r_max, bins, width, dimension));
}

RdfPairSums::RdfPairSums(int bins, double min_weight, double max_weight) : bins_(bins) {
  if (!(min_weight > 0.0 && max_weight >= min_weight && std::isfinite(max_weight)))
    throw std::logic_error("RDF pair weights need a finite positive range");
  // min_weight is in [2^(e - 1), 2^e): its last bit is 2^(e - 53); two more bits below for weights that
  // round a little under it. Weights are below 2^E; 2^64 of them below 2^(E + 64).
  int e = 0, top = 0;
  std::frexp(min_weight, &e);
  std::frexp(max_weight, &top);
  low_exponent_ = e - 55;
  limbs_ = (top + 2 + 64 - low_exponent_) / 64 + 2;
  limb_.assign(static_cast<std::size_t>(bins_) * static_cast<std::size_t>(limbs_), 0);
}

RdfPairSums RdfPairSums::empty_copy() const {
  RdfPairSums copy = *this;
  std::fill(copy.limb_.begin(), copy.limb_.end(), 0);
  return copy;
}

void RdfPairSums::add(int bin, double weight) {
  // weight = mantissa 2^(biased - 1075), mantissa < 2^53, for a positive normal double.
  const auto bits = std::bit_cast<std::uint64_t>(weight);
  const int biased = static_cast<int>(bits >> 52);
  const std::uint64_t mantissa = (bits & ((std::uint64_t{1} << 52) - 1)) | (std::uint64_t{1} << 52);
  const int shift = biased - 1075 - low_exponent_;
  if (biased == 0 || biased >= 2047 || shift < 0 || shift / 64 + 1 >= limbs_)
    throw std::logic_error(fmt::format("an RDF pair weight {:g} outside the sums' range", weight));
  std::uint64_t* s = limb_.data() + static_cast<std::size_t>(bin) * static_cast<std::size_t>(limbs_);
  int k = shift / 64;
  const int bit = shift % 64;
  const std::uint64_t lo = mantissa << bit, hi = bit ? mantissa >> (64 - bit) : 0;
  s[k] += lo;
  std::uint64_t carry = s[k] < lo;
  const std::uint64_t before = s[k + 1];
  s[k + 1] += hi + carry;  // hi + carry < 2^53
  carry = s[k + 1] < before;
  for (k += 2; carry; ++k) {
    if (k >= limbs_) throw std::logic_error("an RDF pair sum overflowed");
    carry = ++s[k] == 0;
  }
}

void RdfPairSums::merge(const RdfPairSums& other) {
  if (other.bins_ != bins_ || other.limbs_ != limbs_ || other.low_exponent_ != low_exponent_)
    throw std::logic_error("RDF pair sums of different shapes");
  merge_words(other.limb_);
}

void RdfPairSums::merge_words(const std::vector<std::uint64_t>& words) {
  if (words.size() != limb_.size()) throw std::logic_error("RDF pair sums of different shapes");
  for (int b = 0; b < bins_; ++b) {
    const std::size_t at = static_cast<std::size_t>(b) * static_cast<std::size_t>(limbs_);
    if (add_fixed_point_limbs(limb_.data() + at, words.data() + at, limbs_)) throw std::logic_error("an RDF pair sum overflowed");
  }
}

bool add_fixed_point_limbs(std::uint64_t* sum, const std::uint64_t* addend, int limbs) {
  std::uint64_t carry = 0;
  for (int k = 0; k < limbs; ++k) {
    const std::uint64_t a = sum[k] + addend[k];
    const std::uint64_t c1 = a < sum[k];
    sum[k] = a + carry;
    carry = c1 | (sum[k] < a);
  }
  return carry != 0;
}

double RdfPairSums::sum(int bin) const {
  const std::uint64_t* s = limb_.data() + static_cast<std::size_t>(bin) * static_cast<std::size_t>(limbs_);
  int top = limbs_ - 1;
  while (top >= 0 && s[top] == 0) --top;
  if (top < 0) return 0.0;
  if (top == 0) return std::ldexp(static_cast<double>(s[0]), low_exponent_);  // the conversion rounds to nearest
  // The 64 bits below and at the highest set bit p, with the lowest set when any bit below them is (which
  // decides a tie without changing any other rounding: 11 bits are dropped), rounded to nearest even.
  const int p = 64 * top + 63 - std::countl_zero(s[top]);
  const int low = p - 63, limb = low / 64, offset = low % 64;
  std::uint64_t window = s[limb] >> offset;
  if (offset) window |= s[limb + 1] << (64 - offset);
  bool sticky = offset && (s[limb] & ((std::uint64_t{1} << offset) - 1)) != 0;
  for (int k = 0; k < limb && !sticky; ++k) sticky = s[k] != 0;
  if (sticky) window |= 1;
  return std::ldexp(static_cast<double>(window), low + low_exponent_);
}

double ball_overlap_volume(int dimension, double radius, double distance) {
  const double phi = std::acos(std::clamp(0.5 * distance / radius, 0.0, 1.0));
  const double sine = std::sin(phi), cosine = std::cos(phi);
  // J_0 = phi, J_1 = 1 - cos phi, J_m = -sin^(m-1) phi cos phi / m + (m - 1) / m J_(m-2).
  double j_even = phi, j_odd = 1.0 - cosine, power = sine;  // power = sin^(m-1) for the m being computed
  for (int m = 2; m <= dimension; ++m) {
    double& j = m % 2 == 0 ? j_even : j_odd;
    j = -power * cosine / m + (m - 1.0) / m * j;
    power *= sine;
  }
  const double integral = dimension % 2 == 0 ? j_even : j_odd;
  return 2.0 * unit_ball_volume(dimension - 1) * std::pow(radius, dimension) * integral;
}

RdfPairSums RdfPlan::empty_sums() const {
  if (periodic) return RdfPairSums(bins, 1.0, 1.0);  // the torus has no edge: every weight is 1
  // The weights lie between 1 / |W| (no shift) and 1 / |W intersect (W + d)| at |d| = r_max (halved and
  // doubled against rounding): for the cube 1 / L^N and 1 / (L - r_max)^N, as |d_a| <= r_max.
  const double side = domain.side;
  if (domain.kind == DomainKind::ball)
    return RdfPairSums(bins, 0.5 / domain.measure(dimension), 2.0 / ball_overlap_volume(dimension, 0.5 * side, r_max));
  return RdfPairSums(bins, 0.5 / std::pow(side, dimension), 2.0 / std::pow(side - r_max, dimension));
}

RdfPlan plan_radial_distribution(int dimension, const Domain& domain, std::uint64_t points, const RdfOptions& options) {
  if (points < 2) throw std::invalid_argument("the RDF needs at least 2 points");
  if (domain.kind == DomainKind::sphere)
    throw std::invalid_argument("the RDF is for points in a torus, cube or ball, not on the sphere");
  RdfPlan plan;
  plan.dimension = dimension;
  plan.domain = domain;
  plan.points = points;
  plan.bins = options.bins;
  plan.periodic = domain.periodic();
  const double side = domain.side;
  const double volume = domain.measure(dimension);
  plan.r_max = options.r_max > 0.0 ? options.r_max
                                   : 2.5 * std::pow(volume / static_cast<double>(points), 1.0 / dimension);
  if (plan.periodic) {
    // Below half the side, a pair has one minimum image within r_max: no pair is counted twice.
    if (options.r_max >= 0.5 * side)
      throw std::invalid_argument(fmt::format("a periodic RDF needs r_max below half the side ({:g}), got {:g}", 0.5 * side,
                                              options.r_max));
    if (plan.r_max >= 0.5 * side) plan.r_max = 0.499 * side;
  }
  // The cube's edge correction needs |d_a| < L; the ball's lens, kept away from its vanishing at the
  // diameter, at most the radius.
  if (domain.kind == DomainKind::ball && plan.r_max > 0.5 * side) plan.r_max = 0.5 * side;
  if (plan.r_max >= side) plan.r_max = 0.999 * side;
  check_rdf_resolution(dimension, side, plan.r_max, options.bins);
  return plan;
}

RdfQueries::RdfQueries(const RdfOptions& options, std::uint64_t seed, std::uint64_t points)
    : all_(options.max_queries == 0 || points <= options.max_queries), seed_(seed) {
  if (!all_) keep_ = static_cast<double>(options.max_queries) / static_cast<double>(points);
}

bool RdfQueries::operator()(std::uint64_t index) const {
  return all_ || random_unit(seed_, Stream::rdf_queries, index) < keep_;
}

namespace {

template <int N>
void count_rdf_pairs_impl(const PointSet& points, const std::vector<std::uint32_t>& queries, const RdfPlan& plan,
                          RdfPairSums& sums, int threads, const FractionProgress& progress) {
  const double side = points.domain.side;
  const bool ball = points.domain.kind == DomainKind::ball;
  const PointSetAdaptor<N> adaptor{points};
  // nanoflann's tree with leaves of nearest_other's size, searched by nearest_other::rows_within in the
  // widest build this CPU runs (the same pairs at the same squared distances in every build).
  const KdTree<N> tree(N, adaptor, kd_tree_params(nearest_other::kLeafSize));  // built by its constructor
  nearest_other::with_rows_within<N>(Simd::best, [&]<int Lanes>(std::integral_constant<int, Lanes>, auto rows_within) {
    const nearest_other::Index<N, Lanes> index(points, tree);
    const std::uint32_t* original = index.original();

    const int bins = plan.bins;
    const double r_max = plan.r_max, r2 = r_max * r_max;
    // The tree searches a little wider than r_max, so that its pruning (bounds that round) cannot lose a
    // pair; each pair is then counted by its own squared distance, summed over the axes in order.
    const double search2 = r2 * (1.0 + 1e-9);
    const double bin_width = r_max / bins;
    constexpr std::int64_t kBlock = 64;
    const auto q = static_cast<std::int64_t>(queries.size());
    const std::int64_t blocks = (q + kBlock - 1) / kBlock;
    std::atomic<std::int64_t> blocks_done{0};
#pragma omp parallel num_threads(resolve_threads(threads))
    {
      RdfPairSums local = sums.empty_copy();
      nearest_other::Scratch<N> scratch = nearest_other::make_scratch(index);
#pragma omp for schedule(dynamic, 1)
      for (std::int64_t b = 0; b < blocks; ++b) {
        if (progress) {  // only the first thread reports
          const std::int64_t done = blocks_done.fetch_add(1, std::memory_order_relaxed);
          if (omp_get_thread_num() == 0) progress(static_cast<double>(done) / static_cast<double>(blocks));
        }
        for (std::int64_t k = b * kBlock; k < std::min(q, (b + 1) * kBlock); ++k) {
          const std::uint32_t i = queries[static_cast<std::size_t>(k)];
          const double* x = points.point(i);
          // The pairs within r_max of x (or, on the torus, of one of its images): each pair once. The sums are
          // fixed-point integers, so the order in which the search finds the pairs does not matter.
          const auto count_pairs = [&](const double* position, bool image) {
            rows_within(index, position, search2, scratch, [&](std::uint32_t row, double dist2, const double* block, int lane) {
              const std::uint32_t j = original[row];
              if (j == i && !image) return;
              if (!(dist2 < r2)) return;
              const auto bin = static_cast<int>(std::sqrt(dist2) / bin_width);
              if (bin >= bins) return;
              double overlap = 1.0;  // |W intersect (W + d)|; the torus has no edge
              if (ball)
                overlap = ball_overlap_volume(N, 0.5 * side, std::sqrt(dist2));
              else if (!plan.periodic)  // y_a = block[Lanes a + lane]: the copy of point j just scanned
                for (int a = 0; a < N; ++a) overlap *= side - std::abs(x[a] - block[Lanes * a + lane]);
              local.add(bin, 1.0 / overlap);
            });
          };
          count_pairs(x, false);
          if (plan.periodic)
            for_each_periodic_image<N>(x, points.domain.lo, side, [&] { return r_max; },
                                       [&](const double* image) { count_pairs(image, true); });
        }
      }
#pragma omp critical(dfvn_rdf_pair_sums)
      sums.merge(local);
    }
  });
}

template <int N>
RdfCurve radial_distribution_impl(const PointSet& points, const RdfOptions& options, std::uint64_t seed, int threads,
                                  const FractionProgress& progress) {
  const RdfPlan plan = plan_radial_distribution(N, points.domain, points.size(), options);
  if (plan.periodic) check_in_periodic_box(points);
  const RdfQueries is_query(options, seed, points.size());
  std::vector<std::uint32_t> queries;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (is_query(i)) queries.push_back(static_cast<std::uint32_t>(i));
  RdfPairSums sums = plan.empty_sums();
  count_rdf_pairs_impl<N>(points, queries, plan, sums, threads, progress);
  return finish_radial_distribution(plan, sums, queries.size());
}

}  // namespace

void count_rdf_pairs(const PointSet& set, const std::vector<std::uint32_t>& queries, const RdfPlan& plan,
                     RdfPairSums& sums, int threads, const FractionProgress& progress) {
  if (set.dimension != plan.dimension || !(set.domain == plan.domain))
    throw std::logic_error("RDF pairs counted in a set of another dimension or box than the plan's");
  dispatch_dimension(set.dimension, [&]<int N>() { count_rdf_pairs_impl<N>(set, queries, plan, sums, threads, progress); });
}

RdfCurve finish_radial_distribution(const RdfPlan& plan, const RdfPairSums& sums, std::uint64_t queries) {
  const int n = plan.dimension, bins = plan.bins;
  RdfCurve curve;
  curve.r_max = plan.r_max;
  curve.queries = queries;
  const double bin_width = plan.r_max / bins;
  const double volume = plan.domain.measure(n);
  curve.r.resize(static_cast<std::size_t>(bins));
  curve.g.assign(static_cast<std::size_t>(bins), 0.0);
  const double ball = unit_ball_volume(n);
  const double normalisation = volume * volume / (static_cast<double>(queries) * static_cast<double>(plan.points - 1));
  for (int k = 0; k < bins; ++k) {
    const double lo = k * bin_width, hi = (k + 1) * bin_width;
    curve.r[k] = 0.5 * (lo + hi);
    const double shell = ball * (std::pow(hi, n) - std::pow(lo, n));
    curve.g[k] = sums.sum(k) * (normalisation / shell);
  }
  return curve;
}

RdfCurve radial_distribution(const PointSet& points, const RdfOptions& options, std::uint64_t seed, int threads,
                             const FractionProgress& progress) {
  options.validate();
  // Volumes and squared distances of extreme domains overflow: compute at unit scale, where g is the
  // same (it has no unit), and scale r back (stats/distance_scale.hpp). One scale, the domain's or else the
  // coordinates': scaling the scaled set again went back and forth for ever when the two were far apart
  // (points in [0, 1] of a domain of side 1e300), and overflowed the stack.
  double scale = domain_scale(points.domain.side);
  if (scale == 1.0) scale = coordinate_scale(points);
  const auto curve_of = [&](const PointSet& set, const RdfOptions& o) {
    return dispatch_dimension(set.dimension, [&]<int N>() { return radial_distribution_impl<N>(set, o, seed, threads, progress); });
  };
  RdfCurve curve;
  if (scale == 1.0) {
    curve = curve_of(points, options);
  } else {
    RdfOptions scaled = options;
    scaled.r_max /= scale;
    curve = curve_of(scaled_point_set(points, scale), scaled);
    for (double& r : curve.r) r *= scale;
    curve.r_max *= scale;
  }
  if (progress) progress(1.0);
  return curve;
}

}  // namespace dfvn
