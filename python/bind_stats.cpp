// dfvn.nn_stats and dfvn.rdf: the statistics of `dfvn-sample stats` and `--rdf` on any point array;
// dfvn._core._discrepancy, under dfvn.discrepancy (python/dfvn/qmc.py), as scipy.stats.qmc.discrepancy.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "dfvn/core/dimension.hpp"
#include "dfvn/stats/discrepancy.hpp"
#include "dfvn/stats/distance_scale.hpp"
#include "dfvn/stats/point_set_statistics.hpp"
#include "dfvn/stats/radial_distribution.hpp"
#include "checked_def.hpp"
#include "numpy_points.hpp"

namespace dfvn::python {

namespace {

// The library's statistics take an owning PointSet: the points are copied once, O(n N) next to the
// O(n log n) KD-tree work that follows. Throws std::invalid_argument for a side outside [2^-1000, 2^1000]
// (stats/distance_scale.hpp) or a point outside [0, side]^N.
PointSet point_set(const PointRows& in, double domain_side, bool periodic) {
  check_domain_side(domain_side, "domain_side");
  PointSet points{in.dimension, Coordinates(in.data, in.data + in.rows * in.dimension),
                  Domain{periodic ? DomainKind::torus : DomainKind::cube, 0.0, domain_side}};
  check_point_set(points);
  return points;
}

py::dict nn_stats(const PointArray& array, double domain_side, const std::string& knn, bool periodic, int threads) {
  const PointSet points = point_set(point_rows(array, 1, kMaxDimension, 2), domain_side, periodic);
  PointSetStatisticsOptions options;
  options.knn = parse_knn_backend(knn);
  options.threads = threads;
  NearestNeighbourSummary s;
  {
    py::gil_scoped_release unlocked;
    s = measure_point_set(points, options).nearest;
  }
  py::dict out;
  out["points"] = s.points;
  out["min"] = s.min;
  out["q01"] = s.q01;
  out["median"] = s.median;
  out["mean"] = s.mean;
  out["median_scaled"] = s.median_scaled;
  return out;
}

py::tuple rdf(const PointArray& array, double domain_side, double r_max, int bins, std::uint64_t max_queries,
              std::uint64_t seed, bool periodic, int threads) {
  const PointSet points = point_set(point_rows(array, kMinDimension, kMaxDimension, 2), domain_side, periodic);
  RdfOptions options;
  options.r_max = r_max;
  options.bins = bins;
  options.max_queries = max_queries;
  options.validate();
  RdfCurve curve;
  {
    py::gil_scoped_release unlocked;
    curve = radial_distribution(points, options, seed, threads);
  }
  return py::make_tuple(array_owning(std::move(curve.r)), array_owning(std::move(curve.g)));
}

// The library's discrepancy of a set in [0,1]^N (N >= 1); a point outside raises ValueError.
double discrepancy_of(const PointArray& array, const std::string& method, int threads) {
  const DiscrepancyKind kind = parse_discrepancy(method);
  const PointRows rows = point_rows(array, 1, 1 << 20, 1);
  PointSet points{rows.dimension, Coordinates(rows.data, rows.data + rows.rows * rows.dimension), Box{0.0, 1.0}};
  py::gil_scoped_release unlocked;
  return discrepancy(points, kind, threads);
}

}  // namespace

void bind_stats(py::module_& module) {
  using namespace pybind11::literals;
  def_checked(module, "nn_stats", &nn_stats, "points"_a, py::kw_only(), "domain_side"_a = 1.0, "knn"_a = "nanoflann",
             "periodic"_a = false, "threads"_a = 0,
             R"(Nearest-neighbour statistics of a point set in [0, domain_side]^N, N = 1..8 (Table 1's).

Returns a dict: points, min, q01 (1% quantile), median, mean and median_scaled (the median times
(points / volume)^(1/N): 1 for a cubic lattice), as `dfvn-sample stats` computes them. knn: the
exact KD-tree, 'nanoflann' or 'flann' (the same distances). periodic: minimum-image distances on the
torus [0, domain_side)^N (`dfvn-sample stats --periodic`; as scipy's cKDTree(..., boxsize=side)).)");
  def_checked(module, "_discrepancy", &discrepancy_of, "points"_a, "method"_a, "threads"_a = 0,
             "Internal: the discrepancy of points in [0,1]^N (dfvn.discrepancy).");
  def_checked(module, "rdf", &rdf, "points"_a, py::kw_only(), "domain_side"_a = 1.0, "r_max"_a = 0.0, "bins"_a = 50,
             "max_queries"_a = 20000, "seed"_a = 1, "periodic"_a = false, "threads"_a = 0,
             R"(Radial distribution function g(r) of a point set in [0, domain_side]^N, N = 2..8, with the
translation edge correction (E g = 1 for uniform random points). Returns (r, g): bin centres and values.

r_max: 0 = 2.5 mean spacings; bins: number of bins; max_queries: a seeded subset of about this many
query points (0 = all); seed: which subset. periodic: minimum-image distances on the torus, no edge
correction, r_max below half the side. As `dfvn-sample --rdf` computes it.)");
}

}  // namespace dfvn::python
