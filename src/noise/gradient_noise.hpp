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
template <int N>
class QuinticGradientNoise final : public NoiseFunctions<N> {
 public:
  static_assert(N >= kMinDimension && N <= kMaxDimension);
  static constexpr int kCorners = 1 << N;

  explicit QuinticGradientNoise(std::uint64_t seed);

  NoiseSample<N, N - 1> evaluate(const Vec<N>& x) const override;
  double wavenumber() const override;
  double amplitude() const override;

  // The lattice gradient of function i at integer point `lattice` (components in [-1, 1)).
  Vec<N> lattice_gradient(int function, const std::array<std::int64_t, N>& lattice) const;
  const Vec<N>& offset(int function) const { return offsets_[function]; }
  const Eigen::Matrix<double, N, N>& rotation(int function) const { return rotations_[function]; }

 private:
  std::array<Eigen::Matrix<double, N, N>, N - 1> rotations_;
  std::array<Vec<N>, N - 1> offsets_;
  std::array<std::uint64_t, N - 1> keys_;
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
