#include "dfvn/stats/discrepancy.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "dfvn/core/parallel.hpp"

namespace dfvn {

DiscrepancyKind parse_discrepancy(std::string_view name) {
  for (DiscrepancyKind kind : kAllDiscrepancies)
    if (name == to_string(kind) || name == csv_column(kind)) return kind;
  throw std::invalid_argument("unknown discrepancy '" + std::string(name) + "' (allowed: CD, WD, MD, L2-star)");
}

std::string_view to_string(DiscrepancyKind kind) {
  switch (kind) {
    case DiscrepancyKind::centered: return "CD";
    case DiscrepancyKind::wrap_around: return "WD";
    case DiscrepancyKind::mixture: return "MD";
    case DiscrepancyKind::l2_star: return "L2-star";
  }
  return "?";
}

std::string_view csv_column(DiscrepancyKind kind) {
  switch (kind) {
    case DiscrepancyKind::centered: return "cd";
    case DiscrepancyKind::wrap_around: return "wd";
    case DiscrepancyKind::mixture: return "md";
    case DiscrepancyKind::l2_star: return "l2_star";
  }
  return "?";
}

namespace {

// Each discrepancy is  D^2 = C(N) - (2 / n) s sum_i prod_k single(x_ik) + (1 / n^2) sum_i sum_j prod_k pair(x_ik, x_jk),
// with a = |x - 1/2| (Hickernell 1998, Eq. 5.1-5.3; Warnock 1972). The policies give c, s and the
// one-point and two-point factors of one axis: CD C = (13/12)^N, WD C = -(4/3)^N, MD C = (19/12)^N,
// L2-star C = 3^-N and s = 2^-N (Warnock's 2^(1-N) / n is 2 s / n).
struct Centered {
  static double constant(int dimension) { return std::pow(13.0 / 12.0, dimension); }
  static double single_scale(int) { return 1.0; }
  static double single(double, double a) { return 1.0 + 0.5 * a - 0.5 * a * a; }
  static double pair(double xi, double xj, double ai, double aj) { return 1.0 + 0.5 * ai + 0.5 * aj - 0.5 * std::abs(xi - xj); }
};
struct WrapAround {  // no one-point sum: single_scale 0
  static double constant(int dimension) { return -std::pow(4.0 / 3.0, dimension); }
  static double single_scale(int) { return 0.0; }
  static double single(double, double) { return 0.0; }
  static double pair(double xi, double xj, double, double) {
    const double d = std::abs(xi - xj);
    return 1.5 - d * (1.0 - d);
  }
};
struct Mixture {
  static double constant(int dimension) { return std::pow(19.0 / 12.0, dimension); }
  static double single_scale(int) { return 1.0; }
  static double single(double, double a) { return 5.0 / 3.0 - 0.25 * a - 0.25 * a * a; }
  static double pair(double xi, double xj, double ai, double aj) {
    const double d = std::abs(xi - xj);
    return 15.0 / 8.0 - 0.25 * ai - 0.25 * aj - 0.75 * d + 0.5 * d * d;
  }
};
struct L2Star {  // Warnock: T^2 = 3^-N - 2^(1-N)/n sum prod (1 - x^2) + 1/n^2 sum sum prod (1 - max)
  static double constant(int dimension) { return std::pow(3.0, -dimension); }
  static double single_scale(int dimension) { return std::pow(0.5, dimension); }
  static double single(double x, double) { return 1.0 - x * x; }
  static double pair(double xi, double xj, double, double) { return 1.0 - std::max(xi, xj); }
};

// Neumaier's compensated sum: the pair sum is C(N) n^2 plus a small remainder (WD: -(4/3)^N n^2 plus
// a discrepancy that can be 1e-6 of it), so the rounding of a plain running sum over n^2 / 64 blocks
// would show in the result; compensation keeps it at the rounding of the block sums.
class CompensatedSum {
 public:
  void add(double value) {
    const double t = sum_ + value;
    compensation_ += std::abs(sum_) >= std::abs(value) ? (sum_ - t) + value : (value - t) + sum_;
    sum_ = t;
  }
  double value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0.0;
  double compensation_ = 0.0;
};

// Pairs of one row are formed kBlock at a time, axis by axis, so the inner loop runs over contiguous
// coordinates of the transposed set and vectorises.
constexpr std::size_t kBlock = 64;

template <typename Policy>
double discrepancy_with(const std::vector<double>& x, const std::vector<double>& a, std::size_t n, int dimension,
                        int threads, const DiscrepancyProgress& progress) {
  // x, a: dimension x n (axis-major): x[k * n + i] is coordinate k of point i, a = |x - 1/2|.
  std::vector<double> row_single(n), row_pairs(n);
  std::atomic<std::uint64_t> pairs_done{0};
  const double total_pairs = 0.5 * static_cast<double>(n) * static_cast<double>(n + 1);
#pragma omp parallel for schedule(dynamic, 8) num_threads(resolve_threads(threads))
  for (std::int64_t signed_i = 0; signed_i < static_cast<std::int64_t>(n); ++signed_i) {
    const auto i = static_cast<std::size_t>(signed_i);
    double single = 1.0, diagonal = 1.0;
    for (int k = 0; k < dimension; ++k) {
      const double xi = x[k * n + i], ai = a[k * n + i];
      single *= Policy::single(xi, ai);
      diagonal *= Policy::pair(xi, xi, ai, ai);
    }
    // Off-diagonal pairs j > i, added block by block in index order.
    CompensatedSum off_diagonal;
    for (std::size_t j0 = i + 1; j0 < n; j0 += kBlock) {
      const std::size_t width = std::min(kBlock, n - j0);
      std::array<double, kBlock> product;
      product.fill(1.0);
      for (int k = 0; k < dimension; ++k) {
        const double xi = x[k * n + i], ai = a[k * n + i];
        const double* xj = x.data() + k * n + j0;
        const double* aj = a.data() + k * n + j0;
        for (std::size_t b = 0; b < width; ++b) product[b] *= Policy::pair(xi, xj[b], ai, aj[b]);
      }
      double block_sum = 0.0;
      for (std::size_t b = 0; b < width; ++b) block_sum += product[b];
      off_diagonal.add(block_sum);
    }
    row_single[i] = single;
    row_pairs[i] = diagonal + 2.0 * off_diagonal.value();  // the pair term is symmetric in i, j
    const std::uint64_t done = pairs_done.fetch_add(n - i, std::memory_order_relaxed) + (n - i);
    if (progress && omp_get_thread_num() == 0) progress(static_cast<double>(done) / total_pairs);
  }
  CompensatedSum sum_single, sum_pairs;
  for (std::size_t i = 0; i < n; ++i) {
    sum_single.add(row_single[i]);
    sum_pairs.add(row_pairs[i]);
  }
  const double inverse_n = 1.0 / static_cast<double>(n);
  return Policy::constant(dimension) - 2.0 * inverse_n * Policy::single_scale(dimension) * sum_single.value() +
         inverse_n * inverse_n * sum_pairs.value();
}

}  // namespace

double discrepancy(const PointSet& points, DiscrepancyKind kind, int threads, const DiscrepancyProgress& progress) {
  const std::size_t n = points.size();
  const int dimension = points.dimension;
  if (n == 0 || dimension < 1) throw std::invalid_argument("discrepancy: the point set is empty");
  std::vector<double> x(n * dimension), a(n * dimension);
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < dimension; ++k) {
      const double u = (points.point(i)[k] - points.domain.lo) / points.domain.side;
      if (!(u >= 0.0 && u <= 1.0))
        throw std::invalid_argument(fmt::format(
            "discrepancy: point {} has coordinate {} = {:.17g}, outside the domain [{:g}, {:g}] (set the domain side)", i,
            k, points.point(i)[k], points.domain.lo, points.domain.lo + points.domain.side));
      x[k * n + i] = u;
      a[k * n + i] = std::abs(u - 0.5);
    }
  }
  double value = 0.0;
  switch (kind) {
    case DiscrepancyKind::centered: value = discrepancy_with<Centered>(x, a, n, dimension, threads, progress); break;
    case DiscrepancyKind::wrap_around: value = discrepancy_with<WrapAround>(x, a, n, dimension, threads, progress); break;
    case DiscrepancyKind::mixture: value = discrepancy_with<Mixture>(x, a, n, dimension, threads, progress); break;
    case DiscrepancyKind::l2_star:
      // Rounding can take a zero square slightly below 0; SciPy then returns NaN, we return 0.
      value = std::sqrt(std::max(0.0, discrepancy_with<L2Star>(x, a, n, dimension, threads, progress)));
      break;
  }
  if (progress) progress(1.0);
  return value;
}

}  // namespace dfvn
