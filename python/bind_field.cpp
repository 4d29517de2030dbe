// dfvn.field and dfvn.trace: the field of Eq. 8 and Algorithm 1 at the rows of a NumPy array.
#include <cstdint>
#include <string>

#include <pybind11/pybind11.h>

#include "core/dimension.hpp"
#include "field/evaluate_points.hpp"
#include "integrate/trace_points.hpp"
#include "numpy_points.hpp"

namespace dfvn::python {

namespace {

FieldOptions field_options(double frequency, const std::string& noise) {
  return FieldOptions{parse_noise_basis(noise), frequency};
}

py::tuple field(const PointArray& points, std::uint64_t seed, double frequency, const std::string& noise, int threads) {
  const PointRows in = point_rows(points, kMinDimension, kMaxDimension);
  FieldQuery query;
  query.dimension = in.dimension;
  query.seed = seed;
  query.field = field_options(frequency, noise);
  query.threads = threads;
  py::array_t<double> velocity = new_array(in.rows, in.dimension);
  py::array_t<double> values = new_array(in.rows, in.dimension - 1);
  double* velocity_out = velocity.mutable_data();
  double* values_out = values.mutable_data();
  {
    py::gil_scoped_release unlocked;
    evaluate_field(query, in.data, in.rows, velocity_out, values_out);
  }
  return py::make_tuple(velocity, values);
}

py::array_t<double> trace(const PointArray& points, double time, std::uint64_t seed, double frequency,
                          const std::string& noise, const std::string& integrator, const std::string& reprojection,
                          int steps, int threads) {
  const PointRows in = point_rows(points, kMinDimension, kMaxDimension);
  TracePointsQuery query;
  query.dimension = in.dimension;
  query.seed = seed;
  query.field = field_options(frequency, noise);
  query.trace.integrator = parse_integrator(integrator);
  query.trace.reprojection = parse_reprojection(reprojection);
  query.trace.steps = steps;
  query.time = time;
  query.threads = threads;
  py::array_t<double> out = new_array(in.rows, in.dimension);
  double* out_data = out.mutable_data();
  {
    py::gil_scoped_release unlocked;
    trace_points(query, in.data, in.rows, out_data);
  }
  return out;
}

}  // namespace

void bind_field(py::module_& module) {
  using namespace pybind11::literals;
  module.def("field", &field, "points"_a, py::kw_only(), "seed"_a = 1, "frequency"_a = 1.0,
             "noise"_a = std::string(to_string(kDefaultNoiseBasis)), "threads"_a = 0,
             R"(The divergence-free field c(x) = cross(grad f_1, ..., grad f_{N-1}) (Eq. 8) at each point.

points: (n, N) array, N = 2..8 (converted to float64 C order if it is not already).
seed: the field's noise realization. frequency: cycles per unit length (one cycle = 2 pi / k_eff
of the basis), in [2^-50, 2^50]. noise: 'turning-bands', 'simplex' or 'quintic-gradient'.
threads: 0 = all cores (the result never depends on it).

Returns (c, f): c (n, N), the field vector (RMS |c| = 1), and f (n, N-1), the noise values f_i(x);
the same numbers as `dfvn-sample field` writes.)");
  module.def("trace", &trace, "points"_a, "t"_a, py::kw_only(), "seed"_a = 1, "frequency"_a = 1.0,
             "noise"_a = std::string(to_string(kDefaultNoiseBasis)), "integrator"_a = "rk4",
             "reprojection"_a = "gauss-newton", "steps"_a = 1, "threads"_a = 0,
             R"(Trace each point along the field for time t (Algorithm 1); returns where they end, (n, N).

integrator: 'euler' or 'rk4'; reprojection onto the iso-contours of the f_i after every step:
'none', 'newton' (Eq. 12) or 'gauss-newton' (Eq. 10-11); steps: M, each of length t / M. The field
options are those of dfvn.field. t < 0 traces backwards; a trace reaching the edge of the noise
domain stops there.)");
}

}  // namespace dfvn::python
