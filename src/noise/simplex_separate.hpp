// Simplex noise with one traversal per function: the N-1 functions are one seeded simplex noise S
// evaluated at offset points, n_i(x) = S(x + o_i). This is bitangent noise's reference form (seeds/004:
// cross(grad S(p), grad S(p + (31.416, 47.853, 12.679))) in 3D), generalised to any N; its
// one-traversal optimised form, two (or N-1) gradient sets hashed at the corners of one shared simplex,
// is the simplex basis (noise/simplex_noise.hpp).
#pragma once

#include <cstdint>

#include "dfvn/core/dimension.hpp"
#include "dfvn/noise/noise_functions.hpp"
#include "dfvn/noise/simplex_noise.hpp"

namespace dfvn {

// The offset of function i: o_i = i b, with b the seed's offset vector (31.416, 47.853, 12.679, 113.408)
// for its first four axes (so 3D's o_1 and 4D's o_1 are the document's) and (71.927, 23.114, 89.246,
// 57.381) for axes 5 to 8 (chosen here: no two coordinates in an integer ratio, so no o_i is near a
// lattice vector of another's). o_0 = 0: n_0 is S itself.
template <int N>
Vec<N> simplex_separate_offset(int function);

// The basis interface (NoiseBasis::simplex_separate). S is the first function of SimplexNoise<N>(seed,
// phase), so phase and seed mean what they mean for simplex; k_eff is simplex's (each n_i is a simplex
// noise function); the amplitude is measured (simplex_normalisation.hpp). The functions' gradients are
// independent at every point (their corners are ~60 cells apart, hashed separately), but their radial
// envelopes are not: x and x + o_i sit at fixed relative positions in the lattice, so the envelope of
// n_i is the envelope of n_0 shifted by o_i (README "Two causes of simplex's collapse").
template <int N>
class SimplexSeparateNoiseFunctions final : public NoiseFunctions<N> {
 public:
  explicit SimplexSeparateNoiseFunctions(std::uint64_t seed, double phase = 0.0);
  NoiseSample<N, N - 1> evaluate(const Vec<N>& x) const override;
  double wavenumber() const override { return wavenumber_; }
  double amplitude() const override { return amplitude_; }

 private:
  SimplexNoise<N> noise_;
  std::array<Vec<N>, N - 1> offsets_;
  double wavenumber_;
  double amplitude_;
};

// Bitangent noise exactly as seeds/004 writes it, with S the first function of SimplexNoise(seed) (the
// document's S is Gustavson's; the construction is the same), for reference and tests:
//   3D: cross(grad S(p), grad S(p + (31.416, 47.853, 12.679)))
//   4D: cross(grad S(p).xyz, grad S(p + (31.416, 47.853, 12.679, 113.408)).xyz), a 3D field at the
//       time p.w whose spatial divergence is zero for every p.w (each gradient's xyz part is the
//       spatial gradient of S at that fixed w).
// Unnormalised (the document's amplitude): the simplex-separate DFVN field in 3D is A^2 times the 3D
// form at s x (field/dfvn_field.hpp).
Vec<3> bitangent_noise_3d(const SimplexNoise<3>& noise, const Vec<3>& p);
Vec<3> bitangent_noise_4d(const SimplexNoise<4>& noise, const Vec<4>& p);
// The document's optimised forms: both gradients from one traversal, two gradient sets hashed at the
// corners of the one simplex (functions 0 and 1 of SimplexNoise, as the simplex basis computes them).
// Another field than the reference form (the second function is not S at an offset), the same cost
// structure as the document's BitangentNoise3D / BitangentNoise4D (bench/results.md compares them).
Vec<3> bitangent_noise_3d_fused(const SimplexNoise<3>& noise, const Vec<3>& p);
Vec<3> bitangent_noise_4d_fused(const SimplexNoise<4>& noise, const Vec<4>& p);

extern template class SimplexSeparateNoiseFunctions<2>;
extern template class SimplexSeparateNoiseFunctions<3>;
extern template class SimplexSeparateNoiseFunctions<4>;
extern template class SimplexSeparateNoiseFunctions<5>;
extern template class SimplexSeparateNoiseFunctions<6>;
extern template class SimplexSeparateNoiseFunctions<7>;
extern template class SimplexSeparateNoiseFunctions<8>;

}  // namespace dfvn
