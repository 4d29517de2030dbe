#include "dfvn/field/dfvn_field.hpp"

#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/direction.hpp"
#include "dfvn/core/hash.hpp"
#include "dfvn/field/cross_product.hpp"
#include "dfvn/noise/noise_domain.hpp"
#include "dfvn/noise/simplex_noise.hpp"
#include "dfvn/noise/simplex_noise.hpp"

namespace dfvn {

FieldKind parse_field_kind(std::string_view name) {
  if (name == "dfvn") return FieldKind::dfvn;
  if (name == "curl") return FieldKind::curl;
  throw std::invalid_argument(fmt::format("unknown field '{}': dfvn or curl", name));
}

std::string_view to_string(FieldKind kind) {
  switch (kind) {
    case FieldKind::dfvn: return "dfvn";
    case FieldKind::curl: return "curl";
  }
  throw std::invalid_argument("unknown field kind");
}

void FieldOptions::validate() const {
  check_noise_frequency(frequency);
  parse_field_kind(to_string(kind));  // an unknown enum value throws
  if (kind == FieldKind::curl && constraint == FieldConstraint::on_sphere)
    throw std::invalid_argument("curl noise has no field on the sphere: --field curl takes the free field, the torus, the cube or the ball");
  if (kind == FieldKind::curl && constraint != FieldConstraint::none && bound != Bound::ramp)
    throw std::invalid_argument(
        "curl noise's boundary is Bridson's (the ramped stream function in 2D, psi_c = alpha psi + (1 - alpha) n (n . psi) in "
        "3D): --field curl in the cube or the ball needs --bound ramp");
  if (!obstacles.empty() && constraint != FieldConstraint::inside_cube && constraint != FieldConstraint::inside_ball)
    throw std::invalid_argument("obstacles lie inside a domain: --obstacle needs --domain cube or ball");
  check_noise_phase(phase);
  transform.validate();
  if (noise == NoiseBasis::steerable && transform.active())
    throw std::invalid_argument("steerable noise takes no --stretch, --time or --lift (it is steered by --steer-dir or --steer-field)");
  if (noise != NoiseBasis::steerable && transform.steer.active())
    throw std::invalid_argument(fmt::format("--steer-dir and --steer-field steer --noise steerable, not {}", to_string(noise)));
  if (transform.time) check_noise_argument(*transform.time, frequency, "--time");
  parse_bound(to_string(bound));  // an unknown enum value throws
  if (periodic && constraint != FieldConstraint::none)
    throw std::invalid_argument(fmt::format("the torus has no boundary: a periodic field takes no {} constraint",
                                            to_string(constraint)));
  if (periodic && noise != NoiseBasis::turning_bands)
    throw std::invalid_argument(fmt::format("the torus needs a periodic noise basis: turning-bands (not {})", to_string(noise)));
  if ((constraint == FieldConstraint::inside_cube || constraint == FieldConstraint::inside_ball) &&
      !(transition_width > 0.0 && transition_width <= 0.25))
    throw std::invalid_argument(
        fmt::format("the boundary's transition width must be in (0, 1/4], got {:g}", transition_width));
  if (transform.rotation != GradientRotation::two_vector &&
      (noise != NoiseBasis::simplex || transform.active() || periodic))
    throw std::invalid_argument(fmt::format(
        "--rotation {} turns the gradients of --noise simplex in 3D (seed 001), without --stretch, --time, --lift or the "
        "torus; got --noise {}{}",
        to_string(transform.rotation), to_string(noise), transform.active() ? " with a transform" : periodic ? " on the torus" : ""));
  flow.validate();
  if (periodic && (!flow.amplitude.empty() || flow.viscous || !flow.bodies.empty() || !flow.vortices.empty()))
    throw std::invalid_argument("the torus takes --octaves only: --amplitude, --viscous, --body and --vortex break its period");
  if (flow.octaves > 1 && transform.lift.active())
    throw std::invalid_argument("--octaves with --lift would add the lift's ramp once per octave: use one of them");
}

namespace {

// Roberts' R_N generator: alpha_j = phi^-(j+1) for phi the positive root of x^(N+1) = x + 1, the
// N-dimensional golden ratio (Newton's iteration from 2 converges to it).
template <int N>
Vec<N> kronecker_alpha() {
  double phi = 2.0;
  for (int k = 0; k < 64; ++k) phi -= (std::pow(phi, N + 1) - phi - 1.0) / ((N + 1) * std::pow(phi, N) - 1.0);
  Vec<N> alpha;
  for (int j = 0; j < N; ++j) alpha[j] = std::fmod(std::pow(phi, -(j + 1)), 1.0);
  return alpha;
}

// The amplitude that gives RMS |c| = 1 over the torus for periodic functions (unit amplitude, scale 1):
// c scales as A^(N-1), so A = (mean |c|^2)^(-1 / (2 (N-1))).
template <int N>
double torus_amplitude(const NoiseFunctions<N>& noise) {
  constexpr int kPoints = 1 << 14;
  const Vec<N> alpha = kronecker_alpha<N>();
  double sum = 0.0;  // in point order: deterministic
  for (int k = 0; k < kPoints; ++k) {
    Vec<N> x;
    for (int j = 0; j < N; ++j) x[j] = std::fmod(0.5 + k * alpha[j], 1.0);
    sum += cross<N>(noise.evaluate(x).gradient).squaredNorm();
  }
  const double mean = sum / kPoints;
  if (!(mean > 0.0 && std::isfinite(mean))) throw std::logic_error("periodic noise field without motion");
  return std::pow(mean, -0.5 / (N - 1));
}

// Curl noise from the gradients of its functions in the basis's units: 2D c = (d psi/dy, -d psi/dx),
// 3D c = curl (psi_1, psi_2, psi_3) with psi_3's gradient g3.
template <int N>
Vec<N> curl_of(const std::array<Vec<N>, N - 1>& g, const Vec<N>& g3) {
  Vec<N> c;
  if constexpr (N == 2) {
    c << g[0][1], -g[0][0];
  } else if constexpr (N == 3) {
    c << g3[1] - g[1][2], g[0][2] - g3[0], g[1][0] - g[0][1];
  } else {
    (void)g, (void)g3;
    c.setConstant(std::numeric_limits<double>::quiet_NaN());
  }
  return c;
}

// The field's functions: the basis itself, or its transform at the options' time.
template <int N>
std::shared_ptr<const NoiseFunctions<N>> field_noise(const FieldOptions& options, std::uint64_t seed, double time,
                                                     double lift_ramp = 0.0) {
  if (options.noise == NoiseBasis::steerable) {  // validate() refuses a transform beside it
    SteerSpec spec = options.transform.steer;
    spec.image_frequency = options.frequency;  // an image covers the unit square of x
    return make_steerable_noise<N>(seed, options.phase, spec);
  }
  if (options.transform.rotation != GradientRotation::two_vector)  // validate(): simplex, no transform, no torus
    return make_rotating_simplex_noise<N>(seed, options.phase, options.transform.rotation);
  if (!options.transform.active())
    return options.periodic ? make_periodic_noise_functions<N>(options.noise, seed, options.frequency, options.phase)
                            : make_noise_functions<N>(options.noise, seed, options.phase);
  return make_transformed_noise<N>(options.noise, seed, options.phase, options.periodic, options.frequency,
                                   options.transform, time, lift_ramp);
}

// The seed of psi_3's basis instance: independent of the seed's own functions ("curl" in ASCII).
std::uint64_t curl_third_seed(std::uint64_t seed) { return hash_combine(mix64(seed), 0x6375726cULL); }

// The seed of octave o >= 1: independent of the seed's own functions and of psi_3's ("oct" in ASCII, plus o).
std::uint64_t octave_seed(std::uint64_t seed, int octave) {
  return hash_combine(mix64(seed), 0x6f637400ULL + static_cast<std::uint64_t>(octave));
}

// The options of octave o's field: 2^o times the frequency, no constraint, no flow.
FieldOptions octave_options(const FieldOptions& options, int octave) {
  FieldOptions o = options;
  o.frequency = std::ldexp(options.frequency, octave);
  o.constraint = FieldConstraint::none;
  o.obstacles = {};
  o.flow = {};
  return o;
}

// A with RMS |A curl n| = 1: the mean of |curl n|^2 over 2^14 Kronecker points in [0, side)^N (the
// basis's units; side 1 on the torus), A = mean^(-1/2) since c is linear in A.
template <int N>
double curl_amplitude(const NoiseFunctions<N>& noise, const NoiseFunctions<N>& third, double side) {
  constexpr int kPoints = 1 << 14;
  const Vec<N> alpha = kronecker_alpha<N>();
  double sum = 0.0;  // in point order: deterministic
  for (int k = 0; k < kPoints; ++k) {
    Vec<N> x;
    for (int j = 0; j < N; ++j) x[j] = side * std::fmod(0.5 + k * alpha[j], 1.0);
    sum += curl_of<N>(noise.evaluate(x).gradient, third.evaluate(x).gradient[0]).squaredNorm();
  }
  const double mean = sum / kPoints;
  if (!(mean > 0.0 && std::isfinite(mean))) throw std::logic_error("curl noise field without motion");
  return 1.0 / std::sqrt(mean);
}

}  // namespace

template <int N>
DfvnField<N>::DfvnField(std::uint64_t seed, const FieldOptions& options)
    : noise_((options.validate(), field_noise<N>(options, seed, options.transform.time.value_or(0.0)))),
      options_(options),
      seed_(seed),
      scale_(options.periodic ? 1.0 : 2.0 * std::numbers::pi * options.frequency / noise_->wavenumber()),
      amplitude_(options.periodic ? torus_amplitude<N>(*noise_) : noise_->amplitude()),
      frequency_(options.periodic ? noise_->wavenumber() / (2.0 * std::numbers::pi) : options.frequency) {
  check_obstacles(N, options.constraint, options.obstacles, options.transition_width);
  flow_active_ = options.flow.active();
  if (flow_active_) {
    check_flow(options.flow, N, options.kind == FieldKind::curl, options.constraint, options.obstacles,
               options.transition_width);
    solids_ = options.obstacles;
    for (const Obstacle& b : body_obstacles(options.flow.bodies)) solids_.push_back(b);
    check_obstacles(N, options.constraint, solids_, options.transition_width);
    octave_weights_ = octave_weights(options.flow.octaves, options.flow.octave_gain);
    for (int o = 1; o < options.flow.octaves; ++o)
      octave_fields_.emplace_back(octave_seed(seed, o), octave_options(options, o));
    const bool ramped = options.bound == Bound::ramp &&
                        (options.constraint == FieldConstraint::inside_cube || options.constraint == FieldConstraint::inside_ball);
    if (ramped && !(options.kind == FieldKind::curl && N == 3))
      for (int o = 0; o < options.flow.octaves; ++o)
        octave_constraints_.push_back(std::make_shared<const ConstraintFunction<N>>(
            options.constraint, std::ldexp(options.transition_width, -o), options.bound));
  }
  if (options.constraint != FieldConstraint::none && !(options.kind == FieldKind::curl && N == 3))
    constraint_ =
        std::make_shared<const ConstraintFunction<N>>(options.constraint, options.transition_width, options.bound);
  if (options.kind == FieldKind::curl) {
    if constexpr (N > 3) {
      throw std::invalid_argument(
          fmt::format("--field curl is Bridson's curl noise in 2D and 3D; dimension {} needs --field dfvn", N));
    } else if constexpr (N == 3) {
      // 64 cycles per side of the measuring box (one cycle = 2 pi / k_eff in the basis's units).
      // psi_3 turns with the phase as psi_1 and psi_2 do (field_noise passes options.phase; it did not before).
      curl_noise_ = field_noise<N>(options, curl_third_seed(seed), options.transform.time.value_or(0.0));
      // With a transform the amplitude is measured below, at time 0 on the flat surface.
      if (!options.transform.active())
        amplitude_ = curl_amplitude<N>(*noise_, *curl_noise_,
                                       options.periodic ? 1.0 : 64.0 * 2.0 * std::numbers::pi / noise_->wavenumber());
    }
    // N == 2: c = (d psi/dy, -d psi/dx) is cross<2>(grad psi), the 2D DFVN field, so the amplitude is
    // the basis's (or on the torus the measured one) as for --field dfvn.
  }
  if (options.transform.active()) {
    const NoiseTransform& t = options.transform;
    // Free field: the transformed basis's derived amplitude (noise/noise_transforms.hpp), which the
    // initialiser took. The torus and 3D curl measure theirs as without a transform, for the functions
    // at time 0 (on the flat surface for a lift), so that A does not depend on the time.
    FieldOptions flat = options;
    flat.transform.lift = {};
    if (t.lift.active()) flat.transform.time = 0.0;
    const bool same = !t.time.value_or(0.0) && !t.lift.active();
    if (options.kind == FieldKind::curl && N == 3) {
      if constexpr (N == 3) {
        const auto at0 = same ? noise_ : field_noise<N>(flat, seed, 0.0);
        const auto third0 = same ? curl_noise_ : field_noise<N>(flat, curl_third_seed(seed), 0.0);
        amplitude_ = curl_amplitude<N>(*at0, *third0,
                                       options.periodic ? 1.0 : 64.0 * 2.0 * std::numbers::pi / at0->wavenumber());
      }
    } else if (options.periodic) {
      amplitude_ = torus_amplitude<N>(same ? *noise_ : *field_noise<N>(flat, seed, 0.0));
    }
    if (t.lift.active()) {
      height_ = make_height_field(t.lift);
      // The ramp in RMS-speed units: f gains ramp * h, so n gains (ramp / A) (s h) in the basis's units.
      if (t.lift.ramp != 0.0) noise_ = field_noise<N>(options, seed, 0.0, t.lift.ramp / amplitude_);
    }
    if (!t.stretch_direction.empty()) {
      for (int j = 0; j < N; ++j) stretch_u_[j] = t.stretch_direction[j];
      stretch_u_ = unit_direction<N>(stretch_u_);
      stretch_s_minus_1_ = t.stretch_factor - 1.0;
    }
  }
  // The noise domain bounds F x; each basis is safe for its own scale s = 2 pi F / k_eff there
  // (noise/noise_domain.hpp), which the checks of the tests assert.
  // A time slice or a lift reads its (N+1)D basis at a scale sqrt((N+1)/N) <= 1.23 times larger: still far
  // inside the bound's margin (turning bands: sqrt(9) * 1.73 * 1.23 * 2^50 + 1 < 2^53).
  assert(options.periodic || (scale_ > 0.0 && scale_ <= 2.5 * options.frequency));
}

template <int N>
bool DfvnField<N>::in_domain(const Vec<N>& x) const {
  for (const DfvnField<N>& octave : octave_fields_)  // the top octave reads the noise fastest
    if (!octave.in_domain(x)) return false;
  if (!in_noise_domain(Vec<N>(options_.frequency * x))) return false;
  // The stretch reads the noise at A x, the lift also at the height h(x).
  if (stretch_s_minus_1_ != 0.0) [[unlikely]] {
    const Vec<N> read = x + (stretch_s_minus_1_ * stretch_u_.dot(x)) * stretch_u_;
    if (!in_noise_domain(Vec<N>(options_.frequency * read))) return false;
  }
  if constexpr (N == 2) {
    if (height_) {
      Vec<2> gradient;
      if (!is_noise_argument(options_.frequency * height_->height(x, gradient))) return false;
    }
  }
  return true;
}

template <int N>
void DfvnField<N>::check_in_domain(const Vec<N>& x, std::string_view what) const {
  const double top_frequency = std::ldexp(options_.frequency, options_.flow.octaves - 1);
  for (int j = 0; j < N; ++j) check_noise_argument(x[j], top_frequency, fmt::format("{}, column {}", what, j + 1));
  if (!in_domain(x))
    throw std::invalid_argument(fmt::format(
        "{}: the point is outside the noise domain where the field reads it (the stretched point A x or the lift's "
        "height h(x), times the frequency, must be below 2^50 in magnitude)",
        what));
}

template <int N>
FieldSample<N> DfvnField<N>::raw_functions(const Vec<N>& x) const {
  const NoiseSample<N, N - 1> noise = noise_->evaluate(scale_ * x);
  FieldSample<N> out;
  const double value_scale = amplitude_ / scale_;
  for (int i = 0; i < N - 1; ++i) {
    out.value[i] = value_scale * noise.value[i];
    out.gradient[i] = amplitude_ * noise.gradient[i];
  }
  return out;
}

template <int N>
FieldSample<N> DfvnField<N>::evaluate_functions(const Vec<N>& x) const {
  if (flow_active_) {
    if constexpr (N == 3) {
      if (curl_noise_) {  // 3D curl noise: psi_1 and psi_2 of the full potential, as evaluate reports them
        std::array<double, 3> psi;
        std::array<Vec<N>, 3> jacobian;
        flow_curl_potential_3d(x, psi, jacobian);
        FieldSample<N> out;
        out.value = {psi[0], psi[1]};
        out.gradient = {jacobian[0], jacobian[1]};
        out.velocity.setConstant(std::numeric_limits<double>::quiet_NaN());
        return out;
      }
    }
    return flow_functions(x);
  }
  FieldSample<N> out = raw_functions(x);
  if (constraint_) constraint_->replace(x, out.value[0], out.gradient[0]);
  if (constraint_ && !options_.obstacles.empty())
    ramp_obstacles<N>(options_.obstacles, options_.transition_width, x, out.value[0], out.gradient[0]);
  out.velocity.setConstant(std::numeric_limits<double>::quiet_NaN());
  return out;
}

template <int N>
FieldSample<N> DfvnField<N>::flow_functions(const Vec<N>& x) const {
  // f_1 of octave o: its own f~_1 through the ramp bound (width w / 2^o) and the obstacles' ramps (same
  // width), times a_o; the other f_i are the weighted sums. The eq13 bound and the sphere act on the sum.
  const bool ramped = !octave_constraints_.empty();
  FieldSample<N> out;
  for (int o = 0; o < options_.flow.octaves; ++o) {
    FieldSample<N> f = o == 0 ? raw_functions(x) : octave_fields_[o - 1].raw_functions(x);
    const double width = std::ldexp(options_.transition_width, -o);
    if (ramped) octave_constraints_[o]->replace(x, f.value[0], f.gradient[0]);
    if (!solids_.empty()) ramp_obstacles<N>(solids_, width, x, f.value[0], f.gradient[0]);
    const double a = octave_weights_[o];
    for (int i = 0; i < N - 1; ++i) {
      out.value[i] = o == 0 ? a * f.value[i] : out.value[i] + a * f.value[i];
      out.gradient[i] = o == 0 ? Vec<N>(a * f.gradient[i]) : Vec<N>(out.gradient[i] + a * f.gradient[i]);
    }
  }
  if (constraint_ && !ramped) constraint_->replace(x, out.value[0], out.gradient[0]);
  // psi -> A psi and, no-slip, -> V psi: (A f)' = A f' + f A'.
  auto modulate = [&](double factor, const Vec<N>& grad_factor) {
    out.gradient[0] = factor * out.gradient[0] + out.value[0] * grad_factor;
    out.value[0] *= factor;
  };
  Vec<N> grad;
  if (!options_.flow.amplitude.empty()) {
    const double a = flow_amplitude<N>(options_.flow.amplitude, solids_, x, grad);
    modulate(a, grad);
  }
  if (options_.flow.viscous) {
    const double v = viscous_factor<N>(options_.constraint, solids_, options_.transition_width, x, grad);
    modulate(v, grad);
  }
  out.velocity.setConstant(std::numeric_limits<double>::quiet_NaN());
  return out;
}

template <int N>
void DfvnField<N>::raw_curl_potential(const Vec<N>& x, std::array<double, 3>& psi, std::array<Vec<N>, 3>& jacobian) const {
  if constexpr (N == 3) {
    const FieldSample<N> functions = raw_functions(x);
    const NoiseSample<N, N - 1> third = curl_noise_->evaluate(scale_ * x);
    psi = {functions.value[0], functions.value[1], amplitude_ / scale_ * third.value[0]};
    jacobian = {functions.gradient[0], functions.gradient[1], Vec<N>(amplitude_ * third.gradient[0])};
  } else {
    (void)x, (void)psi, (void)jacobian;
    throw std::logic_error("3D curl potential of a field that is not 3D");
  }
}

template <int N>
void DfvnField<N>::flow_curl_potential_3d(const Vec<N>& x, std::array<double, 3>& psi,
                                          std::array<Vec<N>, 3>& jacobian) const {
  if constexpr (N == 3) {
    // Figure 2's psi = A(x) sum_o a_o B_o[psi_o] + B[vortices], B_o Bridson's boundary (Eq. 5) at every solid
    // with the octave's width; no-slip: that sum times V(x); then the bodies' blended rigid potentials.
    const bool inviscid = !options_.flow.viscous;
    const FlowOptions& flow = options_.flow;
    psi = {0.0, 0.0, 0.0};
    jacobian = {Vec<3>::Zero(), Vec<3>::Zero(), Vec<3>::Zero()};
    for (int o = 0; o < flow.octaves; ++o) {
      std::array<double, 3> p;
      std::array<Vec<3>, 3> j;
      if (o == 0) raw_curl_potential(x, p, j);
      else octave_fields_[o - 1].raw_curl_potential(x, p, j);
      if (inviscid)
        bridson_boundary_3d(options_.constraint, solids_, std::ldexp(options_.transition_width, -o), x, p, j);
      for (int i = 0; i < 3; ++i) {
        psi[i] += octave_weights_[o] * p[i];
        jacobian[i] += octave_weights_[o] * j[i];
      }
    }
    Vec<3> grad;
    if (!flow.amplitude.empty()) {
      const double a = flow_amplitude<3>(flow.amplitude, solids_, x, grad);
      for (int i = 0; i < 3; ++i) {
        jacobian[i] = a * jacobian[i] + psi[i] * grad;
        psi[i] *= a;
      }
    }
    if (!flow.vortices.empty()) {
      std::array<double, 3> p{0.0, 0.0, 0.0};
      std::array<Vec<3>, 3> j{Vec<3>::Zero(), Vec<3>::Zero(), Vec<3>::Zero()};
      for (const Vortex& v : flow.vortices) add_vortex_potential(v, x, p, j);
      if (inviscid) bridson_boundary_3d(options_.constraint, solids_, options_.transition_width, x, p, j);
      for (int i = 0; i < 3; ++i) {
        psi[i] += p[i];
        jacobian[i] += j[i];
      }
    }
    if (flow.viscous) {
      const double v = viscous_factor<3>(options_.constraint, solids_, options_.transition_width, x, grad);
      for (int i = 0; i < 3; ++i) {
        jacobian[i] = v * jacobian[i] + psi[i] * grad;
        psi[i] *= v;
      }
    }
    for (const RigidBody& b : flow.bodies) add_body_potential(b, x, psi, jacobian);
  } else {
    (void)x, (void)psi, (void)jacobian;
    throw std::logic_error("3D curl potential of a field that is not 3D");
  }
}

template <int N>
FieldSample<N> DfvnField<N>::evaluate(const Vec<N>& x) const {
  if constexpr (N == 3) {
    if (curl_noise_ && (options_.constraint != FieldConstraint::none || flow_active_)) {
      // Bridson's boundaries (and the flow's terms): curl of psi_c
      FieldSample<N> out;
      std::array<double, 3> psi;
      std::array<Vec<N>, 3> jacobian;
      curl_potential_3d(x, psi, jacobian);
      out.value = {psi[0], psi[1]};
      out.gradient = {jacobian[0], jacobian[1]};
      out.velocity = curl_of<N>(out.gradient, jacobian[2]);
      return out;
    }
  }
  FieldSample<N> out = evaluate_functions(x);
  if constexpr (N == 3) {
    if (curl_noise_) {
      const Vec<N> g3 = amplitude_ * curl_noise_->evaluate(scale_ * x).gradient[0];
      out.velocity = curl_of<N>(out.gradient, g3);  // Bridson et al. 2007, curl psi
      return out;
    }
  }
  // Eq. (8); in 2D also curl noise's (d psi/dy, -d psi/dx)
  out.velocity = cross<N>(out.gradient);
  return out;
}

template <int N>
std::array<double, 3> DfvnField<N>::curl_potential(const Vec<N>& x) const {
  if (options_.kind != FieldKind::curl || N > 3) throw std::logic_error("curl_potential of a field that is no curl noise");
  std::array<double, 3> psi{0.0, 0.0, 0.0};
  if constexpr (N == 3) {
    std::array<Vec<N>, 3> jacobian;
    curl_potential_3d(x, psi, jacobian);
  } else {
    psi[0] = evaluate_functions(x).value[0];
  }
  return psi;
}

template <int N>
void DfvnField<N>::curl_potential_3d(const Vec<N>& x, std::array<double, 3>& psi, std::array<Vec<N>, 3>& jacobian) const {
  if (flow_active_) return flow_curl_potential_3d(x, psi, jacobian);
  if constexpr (N == 3) {
    const FieldSample<N> functions = raw_functions(x);  // no constraint_ for 3D curl noise
    const NoiseSample<N, N - 1> third = curl_noise_->evaluate(scale_ * x);
    psi = {functions.value[0], functions.value[1], amplitude_ / scale_ * third.value[0]};
    jacobian = {functions.gradient[0], functions.gradient[1], Vec<N>(amplitude_ * third.gradient[0])};
    if (options_.constraint != FieldConstraint::none)
      bridson_boundary_3d(options_.constraint, options_.obstacles, options_.transition_width, x, psi, jacobian);
  } else {
    (void)x, (void)psi, (void)jacobian;
    throw std::logic_error("3D curl potential of a field that is not 3D");
  }
}

template <int N>
bool DfvnField<N>::contains(const Vec<N>& x) const {
  return satisfies_constraint<N>(options_.constraint, x) &&
         outside_obstacles<N>(flow_active_ ? solids_ : options_.obstacles, x);
}

template class DfvnField<2>;
template class DfvnField<3>;
template class DfvnField<4>;
template class DfvnField<5>;
template class DfvnField<6>;
template class DfvnField<7>;
template class DfvnField<8>;

}  // namespace dfvn
