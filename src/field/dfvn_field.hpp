// The divergence-free vector noise field c(x) = cross(grad f_1, ..., grad f_{N-1}) (Eq. 8).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string_view>

#include "dfvn/core/dimension.hpp"
#include "dfvn/field/constraint.hpp"
#include "dfvn/noise/noise_functions.hpp"

namespace dfvn {

template <int N>
struct FieldSample {
  Vec<N> velocity;                       // c(x)
  std::array<double, N - 1> value;       // f_i(x)
  std::array<Vec<N>, N - 1> gradient;    // grad f_i(x)
};

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
  // The phase alpha in radians (rotating gradients, noise/noise_functions.hpp): every gradient of the basis
  // turns in its own seeded plane, so the field has period 2 pi in alpha, and for every fixed alpha its
  // f_i are C2 and c is exactly divergence-free with RMS |c| = 1. 0 is the field before phases existed.
  double phase = 0.0;

  // throws std::invalid_argument unless the frequency is finite and positive, the phase finite, the constraint's
  // transition width is in (0, 1/4] and a periodic field has a periodic basis and no constraint
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
  std::uint64_t seed() const { return seed_; }

 private:
  std::shared_ptr<const NoiseFunctions<N>> noise_;  // shared: a field is cheap to copy
  std::shared_ptr<const ConstraintFunction<N>> constraint_;  // null: the free field
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
