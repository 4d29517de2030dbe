// dfvn.sample: one point set of any method, generated exactly as `dfvn-sample --points` writes it.
#include <cstdint>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "dfvn/core/dimension.hpp"
#include "dfvn/experiment/experiment.hpp"
#include "numpy_points.hpp"

namespace dfvn::python {

namespace {

// A UserWarning; raises instead when the warnings filter turns it into an error.
void warn(const std::string& text) {
  if (PyErr_WarnEx(PyExc_UserWarning, text.c_str(), 1) < 0) throw py::error_already_set();
}

struct SampleArguments {
  std::string method;
  int dim = 0;
  std::optional<int> grid;
  std::optional<std::uint64_t> n;
  std::uint64_t seed = 1;
  std::string protocol;
  bool scramble = true;
  double radius = 0.0;
  int ncandidates = 30;
  std::string noise;
  double frequency = 0.0;
  double step_scale = 0.0;
  std::string integrator;
  std::string reprojection;
  int steps = 1;
  std::optional<std::string> domain;
  std::string domain_mode;
  std::optional<std::string> bound;
  int threads = 0;
  double max_memory_gib = 0.0;
};

SampleConfig sample_config(const SampleArguments& a) {
  if (a.grid.has_value() == a.n.has_value())
    throw py::value_error("give exactly one of grid (K: a K^N lattice) or n (a point count)");
  if (a.dim < kMinDimension || a.dim > kMaxDimension)
    throw py::value_error("dim must be in " + std::to_string(kMinDimension) + ".." + std::to_string(kMaxDimension) +
                          ", got " + std::to_string(a.dim));
  SampleConfig config;
  config.dimension = a.dim;
  if (a.grid) {
    config.grid = *a.grid;
  } else {
    config.count = *a.n;
    config.grid = grid_for_count(a.dim, *a.n);
  }
  config.seed = a.seed;
  config.threads = a.threads;
  config.protocol = parse_protocol(a.protocol);
  config.scramble = a.scramble ? Scramble::owen : Scramble::none;
  config.pds_radius = a.radius;
  config.pds_candidates = a.ncandidates;
  config.cnj.noise = parse_noise_basis(a.noise);
  config.cnj.frequency = a.frequency;
  config.cnj.step_scale = a.step_scale;
  config.cnj.trace.integrator = parse_integrator(a.integrator);
  config.cnj.trace.reprojection = parse_reprojection(a.reprojection);
  config.cnj.trace.steps = a.steps;
  config.cnj.domain_mode = parse_domain_mode(a.domain_mode);
  // As on the command line: without a domain, drop mode or a bound put CNJ in the cube.
  const bool asks_for_a_boundary = config.cnj.domain_mode == DomainMode::drop || a.bound.has_value();
  config.cnj.domain = a.domain ? parse_cnj_domain(*a.domain) : (asks_for_a_boundary ? CnjDomain::cube : kDefaultCnjDomain);
  if (a.bound) {
    if (config.cnj.domain == CnjDomain::torus || config.cnj.domain_mode == DomainMode::drop)
      throw py::value_error("bound applies to conformant cnj in domain 'cube' or 'ball'");
    config.cnj.bound = parse_bound(*a.bound);
  }
  config.max_memory_gib = a.max_memory_gib;
  return config;
}

py::array_t<double> sample(const SampleArguments& a) {
  const Method method = parse_method(a.method);
  const SampleConfig config = sample_config(a);
  // As scipy.stats.qmc.Sobol.random does.
  if (method == Method::sobol && config.count > 0 && (config.count & (config.count - 1)) != 0)
    warn("The balance properties of Sobol' points require n to be a power of 2.");
  MethodResult result;
  {
    py::gil_scoped_release unlocked;
    result = sample_method(config, method);
  }
  const std::size_t points = result.points.size();
  if (method == Method::pds && config.count > 0 && points < config.count) {
    const std::string text = "Poisson disk sampling saturated: " + std::to_string(points) + " of the " +
                             std::to_string(config.count) + " points requested fit at radius " +
                             std::to_string(result.plan.pds_radius) + "; lower radius for more";
    warn(text);
  }
  return array_owning(std::move(result.points.coordinates), points, static_cast<std::size_t>(config.dimension));
}

}  // namespace

void bind_sampling(py::module_& module) {
  using namespace pybind11::literals;
  const CnjOptions cnj;
  module.def(
      "sample",
      [](const std::string& method, int dim, std::optional<int> grid, std::optional<std::uint64_t> n, std::uint64_t seed,
         const std::string& protocol, bool scramble, double radius, int ncandidates, const std::string& noise,
         double frequency, double step_scale, const std::string& integrator, const std::string& reprojection, int steps,
         const std::optional<std::string>& domain, const std::string& domain_mode, const std::optional<std::string>& bound,
         int threads, double max_memory_gib) {
        return sample(SampleArguments{method, dim, grid, n, seed, protocol, scramble, radius, ncandidates, noise, frequency,
                                      step_scale, integrator, reprojection, steps, domain, domain_mode, bound, threads,
                                      max_memory_gib});
      },
      "method"_a, "dim"_a, py::kw_only(), "grid"_a = py::none(), "n"_a = py::none(), "seed"_a = 1,
      "protocol"_a = "unit", "scramble"_a = true, "radius"_a = 0.0, "ncandidates"_a = 30,
      "noise"_a = std::string(to_string(cnj.noise)), "frequency"_a = cnj.frequency, "step_scale"_a = cnj.step_scale,
      "integrator"_a = std::string(to_string(cnj.trace.integrator)),
      "reprojection"_a = std::string(to_string(cnj.trace.reprojection)), "steps"_a = CnjOptions::kStepsByDomainMode,
      "domain"_a = py::none(), "domain_mode"_a = std::string(to_string(cnj.domain_mode)), "bound"_a = py::none(),
      "threads"_a = 0, "max_memory_gib"_a = 0.0,
      R"(One point set as an (n, dim) float64 array, the same bits as `dfvn-sample --points DIR --format npy`.

method: 'cnj' (curl noise jittering), 'jitter', 'jitter-matched' (jitter at CNJ's RMS displacement),
'pds' (Poisson disk), 'sobol', 'random', 'halton', 'lhs'.
dim: 2..8. Exactly one of grid (K: cnj and jitter move the K^N lattice, the others take its count) or n
(a point count: pds, sobol, random, halton and lhs give n points, or pds fewer when it saturates, with a
warning; cnj and jitter use the lattice K^N nearest to n; sobol warns unless n is a power of 2).
protocol: 'unit' (every method in [0,1]^dim at the density of a cell-centred lattice) or 'paper' (the
paper's Section 5.1, as `dfvn-sample --protocol paper`, its default). scramble: Owen-scrambled Sobol,
digit-permuted Halton (False: neither). radius, ncandidates: Poisson disk radius (0: the protocol's) and
candidates per point. noise, frequency (cycles per lattice spacing), step_scale, integrator,
reprojection, steps (0: the domain's count, 2 in the free field and 1 in the bounded one): CNJ's options,
defaults as the command line's. domain: 'torus' ([0,1)^dim with opposite faces identified, a periodic
field, every point kept), 'cube' or 'ball'; None: the torus, or the cube with drop mode or a bound.
domain_mode: 'conformant' (the field bounded by the domain, every point kept) or 'drop' (the free field,
points that leave are dropped; not on the torus); bound: how the bounded field meets the cube's or
ball's boundary, 'eq13' (None: the default) or 'ramp'.
threads: 0 = all cores (the result never depends on it). max_memory_gib: the memory the set may
need, in GiB (0: 80% of the machine's); a larger set raises ValueError before any work.)");
}

}  // namespace dfvn::python
