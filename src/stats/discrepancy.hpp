// L2 discrepancies of a point set in the unit cube, by their exact closed-form double sums (Hickernell
// 1998 for the centered, wrap-around and mixture discrepancies; Warnock 1972 for L2-star), as
// scipy.stats.qmc.discrepancy computes them.
#pragma once

#include <functional>
#include <string_view>
#include <vector>

#include "dfvn/core/point_set.hpp"

namespace dfvn {

// centered (CD), wrap_around (WD), mixture (MD): the squared discrepancy, as SciPy reports it.
// l2_star: the discrepancy itself (the square root), as SciPy reports it.
enum class DiscrepancyKind { centered, wrap_around, mixture, l2_star };
inline constexpr DiscrepancyKind kAllDiscrepancies[] = {DiscrepancyKind::centered, DiscrepancyKind::wrap_around,
                                                        DiscrepancyKind::mixture, DiscrepancyKind::l2_star};
DiscrepancyKind parse_discrepancy(std::string_view name);  // "CD" | "WD" | "MD" | "L2-star" (SciPy's names)
std::string_view to_string(DiscrepancyKind kind);           // SciPy's name
std::string_view csv_column(DiscrepancyKind kind);          // cd, wd, md, l2_star

// Fraction of the pair sum done; called from the calling thread only.
using DiscrepancyProgress = std::function<void(double fraction)>;

// The discrepancy of `points` after mapping its domain onto [0,1]^N (x -> (x - lo) / side). Throws
// std::invalid_argument if a point lies outside the domain or the set is empty. O(n^2 N) work over
// the pairs i <= j (the pair terms are symmetric), OpenMP-parallel over rows i; each row's sum is
// formed by one thread in index order and the rows are added in index order, so the result does not
// depend on the thread count.
double discrepancy(const PointSet& points, DiscrepancyKind kind, int threads,
                   const DiscrepancyProgress& progress = {});

}  // namespace dfvn
