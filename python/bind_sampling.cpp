// dfvn._core._generate and _plan: one point set of any method, generated exactly as `dfvn-sample --points`
// writes it; the engines of python/dfvn/qmc.py and dfvn.sample are built on them.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <utility>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "dfvn/core/dimension.hpp"
#include "dfvn/experiment/experiment.hpp"
#include "dfvn/sampling/latin_hypercube.hpp"
#include "dfvn/sampling/poisson_disk.hpp"
#include "checked_def.hpp"
#include "numpy_points.hpp"

namespace dfvn::python {

namespace {

struct SampleArguments {
  std::string method;
  int d = 0;
  std::optional<int> grid;
  std::optional<std::uint64_t> n;
  std::uint64_t seed = 1;
  std::string protocol;
  bool scramble = true;
  double radius = 0.0;
  int ncandidates = 30;
  std::string noise;
  double cycles_per_spacing = 0.0;
  double step_scale = 0.0;
  std::string integrator;
  std::optional<std::string> reprojection;  // None: gauss-newton, or none for field 'curl'
  int steps = 1;
  std::optional<std::string> domain;
  std::string domain_mode;
  std::optional<std::string> bound;
  int threads = 0;
  double max_memory_gib = 0.0;
  std::string field = "dfvn";
  double phase = 0.0;
  std::optional<std::string> stretch;  // 'U:S' (python/dfvn turns (U, S) into it)
  std::optional<double> time;
};

// The dimension's name in messages is the caller's (the engines' `d`, sample's `dim`): python/dfvn
// checks it before calling, so the check here only guards the library.
SampleConfig sample_config(const SampleArguments& a) {
  if (a.grid.has_value() == a.n.has_value())
    throw py::value_error("give exactly one of grid (K: a K^N lattice) or n (a point count)");
  if (a.d < kMinDimension || a.d > kMaxDimension)
    throw py::value_error("d must be in " + std::to_string(kMinDimension) + ".." + std::to_string(kMaxDimension) +
                          ", got " + std::to_string(a.d));
  SampleConfig config;
  config.dimension = a.d;
  if (a.grid) {
    config.grid = *a.grid;
  } else {
    config.count = *a.n;
    config.grid = grid_for_count(a.d, *a.n);
  }
  config.seed = a.seed;
  config.threads = a.threads;
  // "unit" (the engines' default): the fair protocol's lattice in the unit cube or torus, as below.
  const Protocol protocol = parse_protocol(a.protocol == "unit" ? "fair" : a.protocol);
  config.scramble = a.scramble ? Scramble::owen : Scramble::none;
  // "unit": Poisson disk at radius 1/K unless given, as the engines have always had it.
  config.pds_radius = a.radius == 0.0 && a.protocol == "unit" ? 1.0 / config.grid : a.radius;
  config.pds_candidates = a.ncandidates;
  config.cnj.noise = parse_noise_basis(a.noise);
  config.cnj.frequency = a.cycles_per_spacing;
  config.cnj.phase = a.phase;
  if (a.stretch) parse_stretch(*a.stretch, config.cnj.transform);
  config.cnj.transform.time = a.time;
  config.cnj.transform.validate();
  config.cnj.step_scale = a.step_scale;
  config.cnj.trace.integrator = parse_integrator(a.integrator);
  config.cnj.field = parse_field_kind(a.field);
  // As on the command line: curl noise has no reprojection, so none is its default (and only choice).
  config.cnj.trace.reprojection =
      parse_reprojection(a.reprojection.value_or(config.cnj.field == FieldKind::curl ? "none" : "gauss-newton"));
  if (config.cnj.field == FieldKind::curl && config.cnj.trace.reprojection != Reprojection::none)
    throw py::value_error("field 'curl' has no reprojection (its streamlines are not intersections of "
                          "iso-surfaces): reprojection '" + *a.reprojection + "' needs field 'dfvn'");
  if (config.cnj.field == FieldKind::curl && a.d > 3)
    throw py::value_error("field 'curl' is Bridson's curl noise in 2D and 3D; d = " + std::to_string(a.d) +
                          " needs field 'dfvn'");
  config.cnj.trace.steps = a.steps;
  config.cnj.domain_mode = parse_domain_mode(a.domain_mode);
  // As on the command line: without a domain, drop mode or a bound put the set in the cube; so does
  // Poisson disk sampling, which the engines run in the cube as scipy.stats.qmc.PoissonDisk does.
  const bool asks_for_a_boundary =
      config.cnj.domain_mode == DomainMode::drop || a.bound.has_value() || a.method == "pds" || protocol == Protocol::paper;
  config.cnj.domain = a.domain ? parse_domain_kind(*a.domain) : (asks_for_a_boundary ? DomainKind::cube : kDefaultDomainKind);
  if (config.cnj.domain == DomainKind::sphere) throw py::value_error("domain 'sphere' is not a sampler's domain here");
  if (a.bound) {
    if (config.cnj.domain == DomainKind::torus || config.cnj.domain_mode == DomainMode::drop)
      throw py::value_error("bound applies to conformant cnj in domain 'cube' or 'ball'");
    config.cnj.bound = parse_bound(*a.bound);
  }
  config.max_memory_gib = a.max_memory_gib;
  config.use_protocol(protocol);
  return config;
}

// The library names CNJ's per-spacing value after the command line's `sample --frequency`; here it is
// cycles_per_spacing (module.cpp maps --cycles-per-spacing to that keyword), since `frequency` means
// cycles per unit length in Python.
template <class F>
auto per_spacing_named(F&& f) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    std::string message = e.what();
    if (message.find("cycles per lattice spacing") != std::string::npos)
      for (std::size_t at = message.find("--frequency "); at != std::string::npos; at = message.find("--frequency ", at))
        message.replace(at, 11, "--cycles-per-spacing");
    throw std::invalid_argument(message);
  }
}

// One set and its plan: (points, requested, grid, domain_side, saturated). `requested` is the count the
// method was asked for under the protocol (K^N for the lattice methods, the ball's sites for CNJ in the
// ball, n for the others); `saturated` is True when Poisson disk sampling ran out of room first.
py::tuple generate(const SampleArguments& a) {
  const Method method = parse_method(a.method);
  SampleConfig config = sample_config(a);
  config.methods = {method};
  MethodResult result;
  {
    py::gil_scoped_release unlocked;
    result = per_spacing_named([&] { return sample_method(config, method); });
  }
  const std::size_t points = result.points.size();
  const bool saturated = result.facts.saturated.value_or(false);
  return py::make_tuple(
      array_owning(std::move(result.points.coordinates), points, static_cast<std::size_t>(config.dimension)),
      result.plan.requested, config.grid, result.plan.domain.side, saturated, result.plan.pds_radius);
}

// The plan alone: (requested, grid, domain_lo, domain_side), without generating anything.
py::tuple plan(const SampleArguments& a) {
  const Method method = parse_method(a.method);
  SampleConfig config = sample_config(a);
  config.methods = {method};
  per_spacing_named([&] {
    config.validate();
    return 0;
  });
  const MethodPlan p = plan_method(config, method);
  return py::make_tuple(p.requested, config.grid, p.domain.lo, p.domain.side);
}

// dfvn.LatinHypercube in any dimension: the library's generator in [0,1)^d (the bits of
// `dfvn-sample --methods lhs` in 2..8 dimensions).
py::array_t<double> latin_hypercube(int d, std::uint64_t n, std::uint64_t seed, int threads) {
  if (d < 1) throw py::value_error("d must be at least 1, got " + std::to_string(d));
  PointSet points;
  {
    py::gil_scoped_release unlocked;
    points = latin_hypercube_points(d, n, Box{0.0, 1.0}, seed, threads);
  }
  return array_owning(std::move(points.coordinates), n, static_cast<std::size_t>(d));
}

// dfvn.PoissonDisk: the library's process in [0,1]^d stopped after max_points (the first points of a
// longer run: the process does not depend on where it stops). Returns (points, saturated).
py::tuple poisson_disk_points(int d, double radius, int ncandidates, std::uint64_t max_points, std::uint64_t seed,
                              int threads) {
  if (d < kMinDimension || d > kMaxDimension)
    throw py::value_error("d must be in " + std::to_string(kMinDimension) + ".." + std::to_string(kMaxDimension) +
                          " for Poisson disk sampling, got " + std::to_string(d));
  PoissonDiskOptions options;
  options.radius = radius;
  options.candidates = ncandidates;
  options.max_points = max_points;
  options.domain = Box{0.0, 1.0};
  options.validate(d);
  PoissonDiskResult result;
  {
    py::gil_scoped_release unlocked;
    result = poisson_disk(d, options, seed, threads);
  }
  const std::size_t count = result.points.size();
  return py::make_tuple(array_owning(std::move(result.points.coordinates), count, static_cast<std::size_t>(d)),
                        !result.reached_max_points);
}

}  // namespace

void bind_sampling(py::module_& module) {
  using namespace pybind11::literals;
  const CnjOptions cnj;
  // The defaults the Python engines read (python/dfvn/qmc.py), so that they stay the library's.
  py::dict defaults;
  defaults["noise"] = std::string(to_string(cnj.noise));
  defaults["cycles_per_spacing"] = cnj.frequency;
  defaults["step_scale"] = cnj.step_scale;
  defaults["integrator"] = std::string(to_string(cnj.trace.integrator));
  defaults["reprojection"] = std::string(to_string(cnj.trace.reprojection));
  defaults["steps"] = CnjOptions::kStepsByDomainMode;
  defaults["domain_mode"] = std::string(to_string(cnj.domain_mode));
  defaults["field"] = std::string(to_string(cnj.field));
  defaults["min_d"] = kMinDimension;
  defaults["max_d"] = kMaxDimension;
  module.attr("_cnj_defaults") = defaults;
  auto call = [](auto f) {
    return [f](const std::string& method, int d, std::optional<int> grid, std::optional<std::uint64_t> n,
               std::uint64_t seed, const std::string& protocol, bool scramble, double radius, int ncandidates,
               const std::string& noise, double cycles_per_spacing, double step_scale, const std::string& integrator,
               const std::optional<std::string>& reprojection, int steps, const std::optional<std::string>& domain,
               const std::string& domain_mode, const std::optional<std::string>& bound, int threads,
               double max_memory_gib, const std::string& field, double phase,
               const std::optional<std::string>& stretch, const std::optional<double>& time) {
      return f(SampleArguments{method, d, grid, n, seed, protocol, scramble, radius, ncandidates, noise,
                               cycles_per_spacing, step_scale, integrator, reprojection, steps, domain, domain_mode,
                               bound, threads, max_memory_gib, field, phase, stretch, time});
    };
  };
  def_checked(module, "_latin_hypercube", &latin_hypercube, "d"_a, "n"_a, "seed"_a, "threads"_a = 0,
             "Internal: n Latin hypercube points in [0,1)^d (dfvn.LatinHypercube).");
  def_checked(module, "_poisson_disk", &poisson_disk_points, "d"_a, "radius"_a, "ncandidates"_a, "max_points"_a, "seed"_a,
             "threads"_a = 0, "Internal: the first max_points of a Poisson disk process in [0,1]^d, and whether it "
             "saturated first (dfvn.PoissonDisk).");
  const char* doc = "Internal: one point set as `dfvn-sample --points` makes it (python/dfvn/qmc.py calls it).";
  for (const auto& [name, f] : {std::pair{"_generate", &generate}, std::pair{"_plan", &plan}}) {
    def_checked(module, name, call(f), "method"_a, "d"_a, py::kw_only(), "grid"_a = py::none(), "n"_a = py::none(),
               "seed"_a = 1, "protocol"_a = "unit", "scramble"_a = true, "radius"_a = 0.0, "ncandidates"_a = 30,
               "noise"_a = std::string(to_string(cnj.noise)), "cycles_per_spacing"_a = cnj.frequency,
               "step_scale"_a = cnj.step_scale, "integrator"_a = std::string(to_string(cnj.trace.integrator)),
               "reprojection"_a = py::none(),
               "steps"_a = CnjOptions::kStepsByDomainMode, "domain"_a = py::none(),
               "domain_mode"_a = std::string(to_string(cnj.domain_mode)), "bound"_a = py::none(), "threads"_a = 0,
               "max_memory_gib"_a = 0.0, "field"_a = std::string(to_string(cnj.field)), "phase"_a = 0.0,
               "stretch"_a = py::none(), "time"_a = py::none(), doc);
  }
}

}  // namespace dfvn::python
