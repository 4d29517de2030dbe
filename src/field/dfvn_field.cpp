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
  if (options.noise == NoiseBasis::steerable)  // validate() refuses a transform beside it
    return make_steerable_noise<N>(seed, options.phase, options.transform.steer);
  if (!options.transform.active())
    return options.periodic ? make_periodic_noise_functions<N>(options.noise, seed, options.frequency, options.phase)
                            : make_noise_functions<N>(options.noise, seed, options.phase);
  return make_transformed_noise<N>(options.noise, seed, options.phase, options.periodic, options.frequency,
                                   options.transform, time, lift_ramp);
}

// The seed of psi_3's basis instance: independent of the seed's own functions ("curl" in ASCII).
std::uint64_t curl_third_seed(std::uint64_t seed) { return hash_combine(mix64(seed), 0x6375726cULL); }

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
  for (int j = 0; j < N; ++j) check_noise_argument(x[j], options_.frequency, fmt::format("{}, column {}", what, j + 1));
  if (!in_domain(x))
    throw std::invalid_argument(fmt::format(
        "{}: the point is outside the noise domain where the field reads it (the stretched point A x or the lift's "
        "height h(x), times the frequency, must be below 2^50 in magnitude)",
        what));
}

template <int N>
FieldSample<N> DfvnField<N>::evaluate_functions(const Vec<N>& x) const {
  const NoiseSample<N, N - 1> noise = noise_->evaluate(scale_ * x);
  FieldSample<N> out;
  const double value_scale = amplitude_ / scale_;
  for (int i = 0; i < N - 1; ++i) {
    out.value[i] = value_scale * noise.value[i];
    out.gradient[i] = amplitude_ * noise.gradient[i];
  }
  if (constraint_) constraint_->replace(x, out.value[0], out.gradient[0]);
  if (constraint_ && !options_.obstacles.empty())
    ramp_obstacles<N>(options_.obstacles, options_.transition_width, x, out.value[0], out.gradient[0]);
  out.velocity.setConstant(std::numeric_limits<double>::quiet_NaN());
  return out;
}

template <int N>
FieldSample<N> DfvnField<N>::evaluate(const Vec<N>& x) const {
  FieldSample<N> out = evaluate_functions(x);
  if constexpr (N == 3) {
    if (curl_noise_) {
      if (options_.constraint != FieldConstraint::none) {  // Bridson's boundaries: curl of psi_c
        std::array<double, 3> psi;
        std::array<Vec<N>, 3> jacobian;
        curl_potential_3d(x, psi, jacobian);
        out.value = {psi[0], psi[1]};
        out.gradient = {jacobian[0], jacobian[1]};
        out.velocity = curl_of<N>(out.gradient, jacobian[2]);
        return out;
      }
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
  if constexpr (N == 3) {
    const FieldSample<N> functions = evaluate_functions(x);  // no constraint_ for 3D curl noise
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
  return satisfies_constraint<N>(options_.constraint, x) && outside_obstacles<N>(options_.obstacles, x);
}

template class DfvnField<2>;
template class DfvnField<3>;
template class DfvnField<4>;
template class DfvnField<5>;
template class DfvnField<6>;
template class DfvnField<7>;
template class DfvnField<8>;

}  // namespace dfvn
