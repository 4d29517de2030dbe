// dfvn.field and dfvn.trace: the field of Eq. 8 and Algorithm 1 at the rows of a NumPy array.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "dfvn/core/dimension.hpp"
#include "dfvn/field/evaluate_points.hpp"
#include "dfvn/integrate/trace_points.hpp"
#include "checked_def.hpp"
#include "numpy_points.hpp"

namespace dfvn::python {

namespace {

// The field's options as the command line's `field` takes them: domain 'free', 'torus', 'cube' or 'ball';
// the bound and its width only for a bounded one.
FieldOptions field_options(double frequency, const std::string& noise, double phase, const std::string& domain,
                           const std::optional<std::string>& bound, const std::optional<double>& boundary_width,
                           const std::string& field, const std::vector<std::string>& obstacles,
                           const NoiseTransform& transform = {}) {
  FieldOptions o{parse_noise_basis(noise), frequency};
  o.phase = phase;
  o.transform = transform;
  o.kind = parse_field_kind(field);
  const bool bounded = domain == "cube" || domain == "ball";
  if (!bounded && domain != "free" && domain != "torus")
    throw py::value_error("unknown domain '" + domain + "' (allowed: free, torus, cube, ball)");
  if (!bounded && (bound || boundary_width))
    throw py::value_error("bound and boundary_width apply to domain 'cube' or 'ball', not '" + domain + "'");
  o.periodic = domain == "torus";
  if (bounded) {
    o.constraint = domain == "cube" ? FieldConstraint::inside_cube : FieldConstraint::inside_ball;
    o.bound = parse_bound(bound.value_or("eq13"));
    o.transition_width = boundary_width.value_or(0.1);
    for (const std::string& spec : obstacles) o.obstacles.push_back(parse_obstacle(spec));
  } else if (!obstacles.empty()) {
    throw py::value_error("obstacles lie inside a domain: they need domain 'cube' or 'ball', not '" + domain + "'");
  }
  return o;
}

// Bridson's toolbox (field/bridson_flow.hpp) from the keywords, as the command line's --octaves, --octave-gain,
// --amplitude, --viscous, --body and --vortex take them; bad values raise ValueError with the same message.
FlowOptions flow_options(int octaves, double octave_gain, const std::vector<std::string>& amplitude, bool viscous,
                         const std::vector<std::string>& bodies, const std::vector<std::string>& vortices) {
  FlowOptions f;
  f.octaves = octaves;
  f.octave_gain = octave_gain;
  f.viscous = viscous;
  for (const std::string& spec : amplitude) f.amplitude.push_back(parse_amplitude(spec));
  for (const std::string& spec : bodies) f.bodies.push_back(parse_body(spec));
  for (const std::string& spec : vortices) f.vortices.push_back(parse_vortex(spec));
  f.validate();
  return f;
}

// stretch: None, 'U:S' as on the command line, or (U, S) with U a sequence of reals; time: None or a
// real; lift: None or 'plane:SX,SY' / 'bump:H,R[,CX,CY[,SX,SY]]' / 'npy:FILE'; lift_ramp: Figure 9's vertical ramp. Bad
// values raise ValueError with the command line's message.
NoiseTransform noise_transform(const py::object& stretch, const std::optional<double>& time,
                               const std::optional<std::string>& lift, double lift_ramp) {
  NoiseTransform t;
  if (py::isinstance<py::str>(stretch)) {
    parse_stretch(stretch.cast<std::string>(), t);
  } else if (!stretch.is_none()) {
    std::pair<std::vector<double>, double> pair;
    try {
      pair = stretch.cast<std::pair<std::vector<double>, double>>();
    } catch (const py::cast_error&) {
      throw py::value_error("stretch takes 'U:S' or (U, S) with U a sequence of reals and S a real");
    }
    t.stretch_direction = pair.first;
    t.stretch_factor = pair.second;
  }
  t.time = time;
  if (lift) {
    t.lift = parse_lift(*lift);
    t.lift.ramp = lift_ramp;
  } else if (lift_ramp != 0.0) {
    throw py::value_error("lift_ramp applies with lift");
  }
  t.validate();
  return t;
}

py::tuple field(const PointArray& points, std::uint64_t seed, double frequency, const std::string& noise, double phase,
                const std::string& domain, const std::optional<std::string>& bound,
                const std::optional<double>& boundary_width, const std::string& field_kind,
                const std::vector<std::string>& obstacles, int threads,
                const py::object& stretch, const std::optional<double>& time, const std::optional<std::string>& lift,
                double lift_ramp, const py::object& steer, double steer_k, int octaves, double octave_gain,
                const std::vector<std::string>& amplitude, bool viscous, const std::vector<std::string>& bodies,
                const std::vector<std::string>& vortices, const std::string& rotation, int steer_quality,
                const std::optional<std::string>& steer_image) {
  const PointRows in = point_rows(points, kMinDimension, kMaxDimension);
  FieldQuery query;
  query.dimension = in.dimension;
  query.seed = seed;
  query.field = field_options(frequency, noise, phase, domain, bound, boundary_width, field_kind, obstacles,
                              noise_transform(stretch, time, lift, lift_ramp));
  query.field.flow = flow_options(octaves, octave_gain, amplitude, viscous, bodies, vortices);
  query.field.transform.rotation = parse_gradient_rotation(rotation);
  // steer: None, 'circular' or a sequence of N reals (the direction U), with noise='steerable'.
  SteerSpec& spec = query.field.transform.steer;
  if (py::isinstance<py::str>(steer)) {
    if (steer.cast<std::string>() != "circular") throw py::value_error("steer takes 'circular' or a direction U (N reals)");
    spec.circular = true;
  } else if (!steer.is_none()) {
    try {
      spec.direction = steer.cast<std::vector<double>>();
    } catch (const py::cast_error&) {
      throw py::value_error("steer takes 'circular' or a direction U (N reals)");
    }
  }
  spec.k = steer_k;
  spec.quality = steer_quality;
  // steer_image: a .png flow map or a .npy (rows, columns, 2) direction array, as --steer-image.
  if (steer_image) {
    if (!spec.direction.empty() || spec.circular) throw py::value_error("steer and steer_image are two direction fields: give one");
    spec.image = read_steer_image(*steer_image);
  }
  if (query.field.noise != NoiseBasis::steerable && (spec.active() || steer_k != kDefaultSteerK || steer_quality != 0))
    throw py::value_error("steer, steer_k, steer_quality and steer_image steer noise='steerable', not '" + noise + "'");
  if (query.field.noise == NoiseBasis::steerable) check_steer_spec(spec, in.dimension);
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
                          const std::string& noise, double phase, const std::string& integrator,
                          const std::optional<std::string>& reprojection, int steps, const std::string& domain,
                          const std::optional<std::string>& bound, const std::optional<double>& boundary_width,
                          const std::string& field_kind, const std::vector<std::string>& obstacles, int threads,
                          const py::object& stretch, const std::optional<double>& noise_time,
                          const std::optional<std::string>& lift, double lift_ramp, int octaves, double octave_gain,
                          const std::vector<std::string>& amplitude, bool viscous, const std::vector<std::string>& bodies,
                          const std::vector<std::string>& vortices) {
  const PointRows in = point_rows(points, kMinDimension, kMaxDimension);
  TracePointsQuery query;
  query.dimension = in.dimension;
  query.seed = seed;
  query.field = field_options(frequency, noise, phase, domain, bound, boundary_width, field_kind, obstacles,
                              noise_transform(stretch, noise_time, lift, lift_ramp));
  query.field.flow = flow_options(octaves, octave_gain, amplitude, viscous, bodies, vortices);
  query.trace.integrator = parse_integrator(integrator);
  // Not given: gauss-newton, or none for curl noise, which has no reprojection (the tracer refuses one).
  query.trace.reprojection = parse_reprojection(
      reprojection.value_or(query.field.kind == FieldKind::curl ? "none" : "gauss-newton"));
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
  def_checked(module, "field", &field, "points"_a, py::kw_only(), "seed"_a = 1, "frequency"_a = 1.0,
             "noise"_a = std::string(to_string(kDefaultNoiseBasis)), "phase"_a = 0.0, "domain"_a = "free",
             "bound"_a = py::none(), "boundary_width"_a = py::none(),
             "field"_a = std::string(to_string(kDefaultFieldKind)), "obstacles"_a = std::vector<std::string>{}, "threads"_a = 0,
             "stretch"_a = py::none(), "time"_a = py::none(), "lift"_a = py::none(), "lift_ramp"_a = 0.0,
             "steer"_a = py::none(), "steer_k"_a = kDefaultSteerK, "octaves"_a = 1, "octave_gain"_a = kKolmogorovOctaveGain,
             "amplitude"_a = std::vector<std::string>{}, "viscous"_a = false, "bodies"_a = std::vector<std::string>{},
             "vortices"_a = std::vector<std::string>{}, "rotation"_a = std::string(to_string(kDefaultGradientRotation)),
             "steer_quality"_a = 0, "steer_image"_a = py::none(),
             R"(The divergence-free field c(x) = cross(grad f_1, ..., grad f_{N-1}) (Eq. 8) at each point.

points: (n, N) array, N = 2..8 (converted to float64 C order if it is not already).
seed: the field's noise realization. frequency: cycles per unit length (one cycle = 2 pi / k_eff
of the basis), in [2^-50, 2^50]. noise: 'turning-bands', 'simplex', 'quintic-gradient' or 'simplex-separate'.
phase (default 0.0): the noise's phase alpha in radians, any finite real (rotating gradients, as
`dfvn-sample field --phase`): period 2 pi, alpha + pi flips every f_i, 0 is the field without a phase.
domain: 'free' (R^N), 'torus' (the basis's periodic form: period 1 along every axis, at about
`frequency` cycles per unit length; turning-bands only), 'cube' ([0,1]^N) or 'ball' (its inscribed
ball): f_1 turned into the boundary function so that c is tangent to the boundary, by bound 'eq13'
(the paper's Eq. 13, the default) or 'ramp' (Bridson et al. 2007) over boundary_width (length units,
(0, 1/4], default 0.1). field: 'dfvn' (Eq. 8, the default) or 'curl' (Bridson et al. 2007's curl
noise, N = 2 and 3 only: c = (d psi/dy, -d psi/dx), in 3D c = curl (psi_1, psi_2, psi_3) of three
independent functions of the basis; the same RMS |c| = 1 and frequency; domain 'free', 'torus', or
'cube' or 'ball' with bound 'ramp' (Bridson's boundaries); f then holds psi_1..psi_{N-1}). obstacles
(default none): with domain 'cube' or 'ball', spheres 'sphere:CX,CY[,CZ...],R' the field flows around,
as `dfvn-sample field --obstacle`. threads: 0 = all cores (the result never depends on it).
stretch (default None): 'U:S' or (U, S), f_i(A x) with A = I + (S - 1) u u^T, u = U / |U| (as
`dfvn-sample field --stretch`); time (default None): the (N+1)D basis at (x, time), N <= 7 (`--time`);
lift (default None, 2D only): 'plane:SX,SY', 'bump:H,R[,CX,CY[,SX,SY]]' or 'npy:FILE', f(x) = F(x, h(x)) (`--lift`), with
lift_ramp (default 0.0) the vertical ramp of the paper's Figure 9 (`--lift-ramp`).
noise 'steerable' (seed 002, N = 2..4) takes steer: a direction U (N reals, any nonzero length) or
'circular' (`--steer-dir`, `--steer-field circular`), and steer_k (default 0.5, `--steer-k`),
steer_quality (default 0, `--steer-quality`: 0..N) and, in 2D, steer_image (default None: a .png flow
map or a .npy (rows, columns, 2) direction array over the unit square, `--steer-image`) instead of steer.
Bridson et al. 2007's toolbox, as `dfvn-sample field` takes it (docs/FIELDS.md): octaves (default 1:
none) with octave_gain (default 2^(-1/3), Kolmogorov's), amplitude (default []: strings 'constant:A',
'height:Z0,Z1', 'obstacles:D', multiplied), viscous (default False: no-slip walls and obstacles), bodies
(default []: 'sphere:CX,CY,CZ,R,VX,VY,VZ,WX,WY,WZ', field='curl' in 3D) and vortices (default []:
'particle:CX,CY,CZ,WX,WY,WZ,R' or 'ring:CX,CY,CZ,NX,NY,NZ,RR,W,R', field='curl' in 3D).
rotation (default 'two-vector'): how noise='simplex' turns its gradients with the phase in 3D, 'two-vector',
'fast' or 'well-behaved' (seed 001, `--rotation`).

Returns (c, f): c (n, N), the field vector (RMS |c| = 1), and f (n, N-1), the noise values f_i(x);
the same numbers as `dfvn-sample field` writes.)");
  def_checked(module, "trace", &trace, "points"_a, "t"_a, py::kw_only(), "seed"_a = 1, "frequency"_a = 1.0,
             "noise"_a = std::string(to_string(kDefaultNoiseBasis)), "phase"_a = 0.0, "integrator"_a = "rk4",
             "reprojection"_a = py::none(), "steps"_a = 1, "domain"_a = "free", "bound"_a = py::none(),
             "boundary_width"_a = py::none(), "field"_a = std::string(to_string(kDefaultFieldKind)),
             "obstacles"_a = std::vector<std::string>{}, "threads"_a = 0,
             "stretch"_a = py::none(), "time"_a = py::none(), "lift"_a = py::none(), "lift_ramp"_a = 0.0,
             "octaves"_a = 1, "octave_gain"_a = kKolmogorovOctaveGain, "amplitude"_a = std::vector<std::string>{},
             "viscous"_a = false, "bodies"_a = std::vector<std::string>{}, "vortices"_a = std::vector<std::string>{},
             R"(Trace each point along the field for time t (Algorithm 1); returns where they end, (n, N).

integrator: 'euler' or 'rk4'; reprojection onto the iso-contours of the f_i after every step:
'none', 'newton' (Eq. 12) or 'gauss-newton' (Eq. 10-11); default 'gauss-newton', and 'none' with
field='curl', which has no reprojection (its streamlines are not intersections of iso-surfaces; any
other is refused); steps: M, each of length t / M. The field options (phase, stretch, time, lift and
Bridson's octaves, amplitude, viscous, bodies and vortices included: the field at one fixed phase and time) are those of dfvn.field: on the torus the ends are wrapped into [0,1)^N; in the cube or the
ball a trace that a long step carries out is traced again with 2, 4, ..., 64 times the steps (or
stays at its start). t < 0 traces backwards; a trace reaching the edge of the noise domain stops
there.)");
}

}  // namespace dfvn::python
