// Quintic gradient noise (Perlin's "improved noise" with hashed gradients): the shader's noise in
// Table 2, in every dimension, with analytic gradients.
#pragma once

#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "dfvn/core/dimension.hpp"
#include "dfvn/noise/noise_functions.hpp"

namespace dfvn {

// n_i(x) = sum over the 2^N corners c of the lattice cell of y = R_i x + o_i of
//   w_c(u) g_ic . (u - c),   u = y - floor(y) in [0, 1)^N,   w_c(u) = prod_d (c_d ? s(u_d) : 1 - s(u_d)),
// with s the quintic fade (noise/quintic_fade.hpp), i = 0..N-2:
// - g_ic: a gradient hashed from (function, lattice point) with every component uniform in [-1, 1],
//   independently: the distribution of the shader's hash (Quilez's 3D gradient noise; at z = 0 its
//   value and x, y derivatives are exactly this 2D noise, data/PROTOCOL.md Table 2).
// - o_i: an offset uniform in [0, 1)^N, so that no lattice point sits at the origin.
// - R_i: the identity for i = 0 (so the 2D basis is the shader's axis-aligned noise) and a seeded
//   Haar-random rotation for i >= 1. An offset alone would not make the functions independent: the
//   cell coordinates of R x + o and R x + o' differ by a constant, so every function would see the same
//   position in its cell and the gradients would be correlated through it. Rotated lattices are
//   incommensurate, so over space the cell positions (u_0, ..., u_{N-2}) are independent and uniform.
// n is C2 (s' and s'' vanish at 0 and 1), zero at every lattice point, with gradient g_ic there.
// Cost per evaluation: (N - 1) 2^N corners, each ceil(N / 2) hash mixes and O(N) products.
//
// The phase alpha (rotating gradients, McEwan & Gustavson's flow noise, seeds/001, in every dimension):
// the lattice gradient at alpha is g(alpha) = p cos alpha + q sin alpha, p the gradient above (the one of
// alpha = 0) and q a second hashed gradient (same distribution, its own key) made orthogonal to p and
// as long as p (Gram-Schmidt): g turns in the plane of p and q at constant length, period 2 pi,
// g(alpha + pi) = -g(alpha), E[g(0) . g(alpha)] / E|g|^2 = cos alpha. The pair's distribution is mapped
// to itself by the cube's reflections and axis permutations (the construction commutes with them), so
// E[g(alpha) g(alpha)^T] is a multiple of I with the trace of alpha = 0: (1/3) I. The moments below
// and the amplitude use only these second moments (corners independent), so they hold at every alpha.
// The seed's 3D "well-behaved" method is not used (the plane is drawn the same way in every dimension).
// For a fixed alpha the noise is the same C2 form in its corner gradients. Phase 0 evaluates exactly
// the phase-free code (the second gradient is not drawn).
template <int N>
class QuinticGradientNoise final : public NoiseFunctions<N> {
 public:
  static_assert(N >= kMinDimension && N <= kMaxDimension);
  static constexpr int kCorners = 1 << N;

  explicit QuinticGradientNoise(std::uint64_t seed, double phase = 0.0);

  NoiseSample<N, N - 1> evaluate(const Vec<N>& x) const override;
  double wavenumber() const override;
  double amplitude() const override;

  // The lattice gradient of function i at integer point `lattice` (components in [-1, 1)).
  Vec<N> lattice_gradient(int function, const std::array<std::int64_t, N>& lattice) const;
  // The same at the noise's phase: p cos alpha + q sin alpha (the header's comment); p at phase 0.
  Vec<N> rotated_lattice_gradient(int function, const std::array<std::int64_t, N>& lattice) const;
  double phase() const { return phase_; }
  std::uint64_t key(int function) const { return keys_[function]; }  // hashed_gradient's key of function i
  // The odd multiplier of lattice coordinate `axis` in the gradients' hash (gradient_noise.cpp).
  static std::uint64_t lattice_multiplier(int axis);
  const Vec<N>& offset(int function) const { return offsets_[function]; }
  const Eigen::Matrix<double, N, N>& rotation(int function) const { return rotations_[function]; }

 private:
  std::array<Eigen::Matrix<double, N, N>, N - 1> rotations_;
  std::array<Vec<N>, N - 1> offsets_;
  std::array<std::uint64_t, N - 1> keys_;
  std::array<std::uint64_t, N - 1> phase_keys_;  // the keys of the second gradients q
  double phase_ = 0.0, cos_phase_ = 1.0, sin_phase_ = 0.0;

  static Vec<N> hashed_gradient(std::uint64_t key, const std::array<std::int64_t, N>& lattice);
};

// Spatial moments of one function, E n^2 and E|grad n|^2, in closed form (gradient_noise.cpp).
struct GradientNoiseMoments {
  double value2;
  double gradient2;
};
GradientNoiseMoments quintic_gradient_noise_moments(int dimension);

extern template class QuinticGradientNoise<2>;
extern template class QuinticGradientNoise<3>;
extern template class QuinticGradientNoise<4>;
extern template class QuinticGradientNoise<5>;
extern template class QuinticGradientNoise<6>;
extern template class QuinticGradientNoise<7>;
extern template class QuinticGradientNoise<8>;

}  // namespace dfvn
