// The divergence-free vector noise field c(x) = cross(grad f_1, ..., grad f_{N-1}) (Eq. 8).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "dfvn/core/dimension.hpp"
#include "dfvn/field/bridson_flow.hpp"
#include "dfvn/field/constraint.hpp"
#include "dfvn/field/field_transform.hpp"
#include "dfvn/field/obstacles.hpp"
#include "dfvn/noise/noise_functions.hpp"

namespace dfvn {

template <int N>
struct FieldSample {
  Vec<N> velocity;                       // c(x)
  std::array<double, N - 1> value;       // f_i(x)
  std::array<Vec<N>, N - 1> gradient;    // grad f_i(x)
};

// dfvn: the paper's field, c = cross(grad f_1, ..., grad f_{N-1}) (Eq. 8), any N, with reprojection.
// curl: Bridson, Hourihan and Nordenstam's curl noise (2007), 2D and 3D only: c = (d psi/dy, -d psi/dx)
// of one function of the basis in 2D, c = curl (psi_1, psi_2, psi_3) of three independent functions in
// 3D, from the basis's analytic gradients. Its streamlines are not intersections of iso-surfaces, so no
// reprojection exists for it (the tracer refuses one); in the cube and the ball (with obstacles) it takes
// Bridson's boundaries (field/obstacles.hpp), and the torus takes the basis's periodic form.
enum class FieldKind { dfvn, curl };
inline constexpr FieldKind kDefaultFieldKind = FieldKind::dfvn;
FieldKind parse_field_kind(std::string_view name);  // "dfvn" | "curl"; throws std::invalid_argument
std::string_view to_string(FieldKind kind);

struct FieldOptions {
  NoiseBasis noise = kDefaultNoiseBasis;
  // Cycles per unit length, the same for every basis: one cycle is 2 pi / k_eff long, where
  // k_eff = sqrt(E|grad f|^2 / E f^2) is the basis's effective wavenumber (NoiseFunctions::wavenumber).
  double frequency = 1.0;
  // Section 4: f_1 replaced by a boundary (Eq. 13) or surface function (field/constraint.hpp); the
  // transition width w of Eq. 13's alpha, in length units, is used by inside_cube and inside_ball.
  FieldConstraint constraint = FieldConstraint::none;
  double transition_width = 0.0;
  // How f_1 turns into the boundary function of inside_cube and inside_ball (field/constraint.hpp).
  Bound bound = Bound::eq13;
  // The torus [0,1)^N: the basis's periodic form (period 1 along every axis, at about `frequency` cycles
  // per unit length; noise/noise_functions.hpp), with no constraint.
  bool periodic = false;
  // Which field the functions make (FieldKind above); curl needs N <= 3, and with the cube or the ball
  // Bound::ramp (Bridson's boundaries: the ramped stream function in 2D, psi_c in 3D).
  FieldKind kind = kDefaultFieldKind;
  // The phase alpha in radians (rotating gradients, noise/noise_functions.hpp): every gradient of the basis
  // turns in its own seeded plane, so the field has period 2 pi in alpha, and for every fixed alpha its
  // f_i are C2 and c is exactly divergence-free with RMS |c| = 1. 0 is the field before phases existed.
  double phase = 0.0;
  // Where the noise is read (field/field_transform.hpp): --stretch (f_i(A x)), --time (the (N+1)D basis
  // at (x, t)), --lift (2D: F(x, h(x))). None of them: the field before they existed, bit for bit.
  NoiseTransform transform{};
  // Spherical obstacles inside the cube or the ball (field/obstacles.hpp), each with the transition width
  // above as its ramp's width: f_1 times ramp(d / w) for DFVN (any N) and 2D curl noise, Bridson's psi_c
  // for 3D curl noise. Checked against the dimension and the domain by DfvnField<N>.
  std::vector<Obstacle> obstacles = {};
  // Bridson's toolbox (field/bridson_flow.hpp): octaves with a power law, an amplitude, viscous solids,
  // moving rigid spheres and vortices. Its defaults (one octave, nothing else) are the field without it,
  // bit for bit.
  FlowOptions flow = {};

  // throws std::invalid_argument unless the frequency is finite and positive, the phase finite, the
  // constraint's transition width is in (0, 1/4], a periodic field has a periodic basis and no constraint,
  // a curl field has no constraint but the cube or the ball with Bound::ramp, and obstacles have the cube or
  // the ball (their dimension and placement are checked by DfvnField<N>), and the flow fits (check_flow; on
  // the torus only octaves, without a lift)
  void validate() const;
};

// f_i(x) = (A / s) n_i(s x) with n_i the N-1 functions of the basis, s = 2 pi F / k_eff the scale that
// gives F cycles per unit length, and A the basis's amplitude. Then grad f_i(x) = A grad n_i(s x), so
// c = cross(grad f_i) has an RMS magnitude of 1 over space for every dimension, basis and frequency:
// the frequency changes how fast the field varies, never how fast points move. Scaling the f_i by
// constants does not change their iso-contours, so reprojection (Eq. 10-12) keeps working on exactly
// the curves that c is tangent to. With a constraint, f_1 is the constraint's function of f~_1
// (field/constraint.hpp) and the same holds: reprojection then also keeps f_1, the boundary or
// surface function, at its start value.
// Periodic (the torus): s = 1 (the periodic basis is built for its frequency, and a scale would break
// its period), and A is measured per seed, RMS |c| = 1 over the torus: the mean of |c|^2 over 2^14
// points of a Kronecker sequence (x_k = frac(1/2 + k alpha), Roberts' R_N alpha), which integrates a
// smooth periodic function far more accurately than random points (the field's own divergence and
// speed tests measure the result on uniform random points).
// Curl noise (FieldKind::curl): psi_i(x) = (A / s) n_i(s x) with the same s, so the frequency means
// the same; c = curl psi = A (curl n)(s x). In 2D |c| = |grad psi|, which is exactly the 2D DFVN
// field's magnitude, so A is the basis's own amplitude (derived, not measured). In 3D the three
// functions come from two instances of the basis (n_1, n_2 of `seed`; n_3 the first function of an
// independent seed derived from it), and A is measured per seed: A = (mean |curl n|^2)^(-1/2) over the
// 2^14 Kronecker points above, spread over a box of 64 cycles per side (on the torus: over the torus).
// For isotropic independent functions E|curl n|^2 = 2 E|grad n|^2 (each n_i contributes two of its
// three gradient components, the cross terms have mean 0); the quintic gradient basis and simplex are
// not exactly isotropic and turning bands is isotropic only over seeds, which is why it is measured.
// The tests check RMS |c| within 3% of 1 on 10^5 uniform random points for every basis.
// A transform (options.transform: stretch, time, lift) changes the functions n_i; their amplitude is
// derived in closed form (noise/noise_transforms.hpp: the stretch's ((S^2 (N-1) + 1) / N)^(-1/(2(N-1))),
// the slice's from the (N+1)D basis's), and s = 2 pi F / k_eff with the transformed basis's k_eff (a
// stretch keeps the basis's, so f_i(x) is the unstretched f_i at A x up to that constant; a time slice
// or a lift reports k_{N+1} sqrt(N / (N+1))). On the torus and for 3D curl noise A is measured as above,
// for the functions at time 0, so that it does not depend on the time and the field is continuous in it.
// A lift keeps the amplitude of its flat surface (h = 0): a slope raises the speed, as the paper's
// Figure 9 shows, and its vertical ramp adds ramp * perp(grad h) to c in RMS-speed units.
template <int N>
class DfvnField {
 public:
  static constexpr int kFunctions = N - 1;

  // Throws std::invalid_argument for a bad basis or a frequency outside [kMinNoiseFrequency,
  // kMaxNoiseFrequency] (noise/noise_domain.hpp).
  explicit DfvnField(std::uint64_t seed, const FieldOptions& options = {});

  // evaluate(x) needs x in the noise domain (every |F x_j| < 2^50); callers check their points before
  // evaluating, with in_domain or check_in_domain (which throws std::invalid_argument naming `what`).
  FieldSample<N> evaluate(const Vec<N>& x) const;
  // The f_i and their gradients only, for reprojection, which needs no velocity: the velocity is
  // left NaN, and cross<N>(gradient) gives it later, bit for bit as evaluate would have.
  FieldSample<N> evaluate_functions(const Vec<N>& x) const;
  // Curl noise only (kind() == curl, N <= 3): the vector potential (psi_1, psi_2, psi_3) at x, in 2D
  // (psi, 0, 0); c is its curl (the tests compare c with its central differences). Throws
  // std::logic_error for a dfvn field.
  std::array<double, 3> curl_potential(const Vec<N>& x) const;
  // Whether x lies in the closed domain and outside every obstacle.
  bool contains(const Vec<N>& x) const;
  bool in_domain(const Vec<N>& x) const;
  void check_in_domain(const Vec<N>& x, std::string_view what) const;
  Vec<N> velocity(const Vec<N>& x) const { return evaluate(x).velocity; }

  const FieldOptions& options() const { return options_; }
  // Cycles per unit length: options().frequency, or on the torus the one its integer wave vectors
  // realise (within ~10% of the asked one above about one cycle per unit length).
  double frequency() const { return frequency_; }
  double scale() const { return scale_; }          // s: x -> s x in the basis's own units
  double amplitude() const { return amplitude_; }  // A
  double wavenumber() const { return noise_->wavenumber(); }  // k_eff of the raw basis
  FieldKind kind() const { return options_.kind; }
  std::uint64_t seed() const { return seed_; }
  // The basis itself when the field's f_i are exactly raw_functions (the basis at its scale and amplitude):
  // a dfvn field without constraint, obstacles, flow or octaves, whose domain check is the frequency's
  // alone; else null. For kernels that evaluate a known basis their own way, bit for bit as evaluate
  // (warp/warp_lanes.hpp); a transform (stretch, time, lift) wraps the basis in another type.
  const NoiseFunctions<N>* plain_basis() const {
    const bool plain = options_.kind == FieldKind::dfvn && !constraint_ && !flow_active_ && octave_fields_.empty() &&
                       !height_ && stretch_s_minus_1_ == 0.0 && !curl_noise_;
    return plain ? noise_.get() : nullptr;
  }

 private:
  std::shared_ptr<const NoiseFunctions<N>> noise_;  // shared: a field is cheap to copy
  std::shared_ptr<const NoiseFunctions<N>> curl_noise_;  // curl in 3D: psi_3 is its first function
  std::shared_ptr<const HeightField> height_;  // a lift's surface (null without --lift), for the domain check
  Vec<N> stretch_u_ = Vec<N>::Zero();           // the stretch's unit direction (0 without --stretch)
  double stretch_s_minus_1_ = 0.0;
  std::shared_ptr<const ConstraintFunction<N>> constraint_;  // null: the free field (and 3D curl noise)
  // 3D curl noise's potential and its Jacobian rows, with Bridson's boundary applied (and the flow's terms).
  void curl_potential_3d(const Vec<N>& x, std::array<double, 3>& psi, std::array<Vec<N>, 3>& jacobian) const;
  // This field's own basis at its scale and amplitude (one octave, no constraint): values and gradients.
  FieldSample<N> raw_functions(const Vec<N>& x) const;
  // 3D curl noise's raw potential (psi_1, psi_2 of noise_, psi_3 of curl_noise_) and its Jacobian rows.
  void raw_curl_potential(const Vec<N>& x, std::array<double, 3>& psi, std::array<Vec<N>, 3>& jacobian) const;
  // The flow's f_1 (DFVN and 2D curl noise): octaves with their boundary widths, then amplitude and viscosity.
  FieldSample<N> flow_functions(const Vec<N>& x) const;
  void flow_curl_potential_3d(const Vec<N>& x, std::array<double, 3>& psi, std::array<Vec<N>, 3>& jacobian) const;
  // Octaves 1..K-1 (octave 0 is this field's own basis): fields of the same options at 2^o times the
  // frequency, independently seeded, without constraint or flow; their weights a_o (field/bridson_flow.hpp)
  // and, for the ramp bound, the boundary function of each octave's width w / 2^o.
  std::vector<DfvnField<N>> octave_fields_;
  std::vector<double> octave_weights_;
  std::vector<std::shared_ptr<const ConstraintFunction<N>>> octave_constraints_;
  std::vector<Obstacle> solids_;  // the obstacles, then the bodies as spheres
  bool flow_active_ = false;
  FieldOptions options_;
  std::uint64_t seed_;
  double scale_;
  double amplitude_;
  double frequency_;
};

extern template class DfvnField<2>;
extern template class DfvnField<3>;
extern template class DfvnField<4>;
extern template class DfvnField<5>;
extern template class DfvnField<6>;
extern template class DfvnField<7>;
extern template class DfvnField<8>;

}  // namespace dfvn
