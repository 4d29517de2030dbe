// The noise basis: N-1 scalar noise functions on R^N with analytic gradients, chosen once from an enum
// and evaluated through one interface (the policy the DFVN field is built on).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "dfvn/core/dimension.hpp"

namespace dfvn {

// Values and gradients of M scalar noise functions at one point.
template <int N, int M>
struct NoiseSample {
  std::array<double, M> value;
  std::array<Vec<N>, M> gradient;
};

// simplex: the paper's construction (Perlin's simplex noise, C2 kernel, one shared traversal for all
// functions; noise/simplex_noise.hpp). Its field collapses from 4D on: kept to show that construction.
// turning_bands: 2N one-dimensional quintic gradient noises per function along the rows of two random
// orthonormal frames (noise/turning_bands.hpp): healthy in every dimension, the default.
// quintic_gradient: Perlin-style gradient noise with the quintic fade on a lattice, 2^N corners per
// function (noise/gradient_noise.hpp): the noise of the paper's image-warping shader (Table 2).
// simplex_separate: the same simplex noise, one traversal per function at an offset point,
// n_i(x) = S(x + o_i) (noise/simplex_separate.hpp): bitangent noise's reference form (seeds/004), where
// simplex is its one-traversal optimised form; the two separate the causes of simplex's collapse.
// steerable: seed 002's steerable Perlin noise (noise/steerable_noise.hpp), 2D-4D only, which needs its
// direction field (SteerSpec): made by make_steerable_noise, not make_noise_functions, and therefore not in
// kAllNoiseBases (the bases every dimension and every transform takes), only in kNamedNoiseBases.
enum class NoiseBasis { simplex, turning_bands, quintic_gradient, simplex_separate, steerable };
inline constexpr NoiseBasis kDefaultNoiseBasis = NoiseBasis::turning_bands;
inline constexpr NoiseBasis kAllNoiseBases[] = {NoiseBasis::simplex, NoiseBasis::turning_bands,
                                                 NoiseBasis::quintic_gradient, NoiseBasis::simplex_separate};
inline constexpr NoiseBasis kNamedNoiseBases[] = {NoiseBasis::simplex, NoiseBasis::turning_bands,
                                                   NoiseBasis::quintic_gradient, NoiseBasis::simplex_separate,
                                                   NoiseBasis::steerable};

NoiseBasis parse_noise_basis(std::string_view name);  // throws std::invalid_argument listing the names
std::string_view to_string(NoiseBasis basis);
std::string noise_basis_names();  // "simplex, turning-bands, quintic-gradient, simplex-separate, steerable"

// N-1 independent, seeded, deterministic C2 noise functions n_i: R^N -> R with zero mean.
template <int N>
class NoiseFunctions {
 public:
  virtual ~NoiseFunctions() = default;

  // n_i(x) and grad n_i(x) for i = 0..N-2.
  virtual NoiseSample<N, N - 1> evaluate(const Vec<N>& x) const = 0;

  // k_eff = sqrt(E|grad n_i|^2 / E n_i^2) over space, in radians per unit of x: one "cycle" of the
  // noise is 2 pi / k_eff long. Every basis reports its own, so a frequency means the same for all.
  virtual double wavenumber() const = 0;

  // A such that the field of the functions (A / s) n_i(s x) has RMS |cross(grad ...)| = 1 for every
  // scale s (the gradients are A grad n_i(s x), independent of s).
  virtual double amplitude() const = 0;
};

// The basis's functions for `seed` at the phase `phase` in radians (rotating gradients: every gradient of
// every basis turns in its own seeded plane, g(alpha) = p cos alpha + q sin alpha, so each function has
// period 2 pi in the phase, changes sign at pi, and keeps its k_eff and amplitude; each basis's header
// says how, and README "Fields that move: --phase" why). Phase 0 is bit for bit the phase-free basis.
// Throws std::invalid_argument for an unknown basis, for steerable (it needs a SteerSpec:
// make_steerable_noise) or a non-finite phase.
template <int N>
std::shared_ptr<const NoiseFunctions<N>> make_noise_functions(NoiseBasis basis, std::uint64_t seed, double phase = 0.0);

// The basis's periodic form for the torus [0,1)^N: functions with period 1 along every axis, evaluated
// at x itself (no scale), at about `frequency` cycles per unit length (wavenumber() / 2 pi says exactly).
// Only turning bands has one (noise/turning_bands.hpp); throws std::invalid_argument for the others and
// for a frequency outside the periodic form's range.
template <int N>
std::shared_ptr<const NoiseFunctions<N>> make_periodic_noise_functions(NoiseBasis basis, std::uint64_t seed,
                                                                       double frequency, double phase = 0.0);

// Throws std::invalid_argument unless the phase is finite.
void check_noise_phase(double phase);

// The phase modulo 2 pi, in [-pi, pi]: the same field (the bases read only cos alpha and sin alpha, which
// the C library computes with an exact reduction for any finite alpha), but a phase that a step can
// still advance: 1e17 + 0.05 is 1e17, whose units in the last place are 16. Taken as atan2(sin, cos), so
// it is the exact reduction to within an ulp of pi; a phase already in [-pi, pi] is returned as it is.
double reduced_phase(double phase);

}  // namespace dfvn
