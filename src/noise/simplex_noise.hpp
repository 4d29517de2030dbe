// Simplex noise in N dimensions with analytic gradients, for several independent functions at once.
#pragma once

#include <array>
#include <cstdint>

#include <memory>

#include "dfvn/core/dimension.hpp"
#include "dfvn/noise/noise_functions.hpp"
#include "dfvn/noise/rotating_gradients.hpp"

namespace dfvn {

// Simplex noise (Perlin 2002, as explained by Gustavson 2005) on R^N.
//
// One call walks the N+1 vertices of the simplex that contains x once and evaluates up to N-1
// independent noise functions there: each function hashes its own gradient at every vertex, while the
// simplex search, the vertex offsets and the radial kernel are shared. This is the "bitangent noise"
// idea (seeds/004: two gradient sets per traversal) generalised to any number of functions.
//
// Smoothness. Vertex v contributes k(|d|^2) (g_v . d) with d = x - v and kernel
// k(s) = (r^2 - s)^4 for s < r^2, 0 otherwise, whose first three derivatives vanish at s = r^2: each
// contribution is C^3 wherever it is defined. The sum is C^2 everywhere only if the kernel of v
// vanishes outside the simplices that have v as a vertex, i.e. r is at most the distance from a
// vertex to its opposite face. That distance is the same, 1/sqrt(2), in every dimension:
//
//   Skewed coordinates are y = x + F (1.x) 1 with F = (sqrt(N+1) - 1) / N. The simplex containing a
//   point has, in skewed coordinates, the vertices v_k = e_{p_1} + ... + e_{p_k} (k = 0..N) for the
//   permutation p that sorts the fractional parts in decreasing order. Its facets are
//     y_{p_k} = y_{p_{k+1}} (opposite v_k, 0 < k < N),  y_{p_1} = 1 (opposite v_0),
//     y_{p_N} = 0 (opposite v_N).
//   In unskewed coordinates y_a - y_b = x_a - x_b, so the first kind of facet is the plane
//   x_a = x_b, and v_k differs by exactly 1 across it: distance 1/sqrt(2). The other two facets are
//   (e_a + F 1).x = const with |e_a + F 1|^2 = 1 + 2F + N F^2 = 1 + F (sqrt(N+1) + 1) = 2, and the
//   opposite vertex lies at skewed distance 1 from it: distance 1/sqrt(2) again.
//
// So r^2 = 1/2 for every N. (Gustavson's 3D code uses 0.6 and the Python port the paper used uses
// 0.70-0.82 for N >= 3: both exceed the bound, so their noise jumps across simplex faces.)
//
// The phase alpha (rotating gradients, McEwan & Gustavson's flow noise, seeds/001, in every dimension):
// the corner gradient at alpha is g(alpha) = p cos alpha + q sin alpha, p the corner's gradient above (the
// one of alpha = 0) and q a second gradient of the same set, hashed again until it is not parallel to p,
// made orthogonal to p and as long as p: g turns in its own plane at constant length, period 2 pi,
// g(alpha + pi) = -g(alpha). The construction commutes with the axis permutations and sign flips that
// map the gradient set to itself, so E[g g^T] stays (E|g|^2 / N) I at every alpha, and k_eff and the
// field's measured amplitude (which depend on the corner gradients only through these second moments:
// each function's gradient is linear in its independent corner gradients) hold at every alpha. Phase 0
// evaluates exactly the phase-free code.
template <int N>
class SimplexNoise {
 public:
  static_assert(N >= kMinDimension && N <= kMaxDimension);
  static constexpr int kMaxFunctions = N - 1;
  static constexpr double kKernelRadius2 = 0.5;

  // `rotation`: how the gradients turn with the phase (noise/rotating_gradients.hpp); fast and well_behaved
  // exist in 3D only (std::invalid_argument otherwise). two_vector is the method described above.
  explicit SimplexNoise(std::uint64_t seed, double phase = 0.0, GradientRotation rotation = kDefaultGradientRotation);

  // Values and gradients of the functions first_function .. first_function + M - 1 at x, computed in
  // one traversal of the simplex. Function indices are in [0, kMaxFunctions).
  template <int M>
  NoiseSample<N, M> evaluate(const Vec<N>& x, int first_function = 0) const;

  // All N-1 functions at once.
  NoiseSample<N, N - 1> evaluate_all(const Vec<N>& x) const { return evaluate<N - 1>(x, 0); }

  std::uint64_t seed() const { return seed_; }
  double phase() const { return phase_; }
  GradientRotation rotation() const { return rotation_; }
  // The corner gradient of hash h at this noise's phase, by its rotation method.
  void corner_gradient(std::uint64_t h, double* g) const { corner_gradient_(*this, h, g); }

 private:
  std::uint64_t seed_;
  double phase_ = 0.0, cos_phase_ = 1.0, sin_phase_ = 0.0;
  GradientRotation rotation_ = kDefaultGradientRotation;
  // The (rotation, phase) policy, chosen once in the constructor.
  using CornerGradient = void (*)(const SimplexNoise&, std::uint64_t, double*);
  CornerGradient corner_gradient_;
  std::uint64_t seed_hash_;  // mix64 of the seed and the noise stream, the start of every vertex hash
};

// k_eff = sqrt(E|grad n|^2 / E n^2) of SimplexNoise<N>, in closed form (see simplex_noise.cpp).
double simplex_wavenumber(int dimension);

// The basis interface over SimplexNoise<N>, with the amplitudes of simplex_normalisation.hpp.
template <int N>
class SimplexNoiseFunctions final : public NoiseFunctions<N> {
 public:
  explicit SimplexNoiseFunctions(std::uint64_t seed, double phase = 0.0,
                                 GradientRotation rotation = kDefaultGradientRotation);
  NoiseSample<N, N - 1> evaluate(const Vec<N>& x) const override { return noise_.evaluate_all(x); }
  double wavenumber() const override { return wavenumber_; }
  double amplitude() const override { return amplitude_; }

 private:
  SimplexNoise<N> noise_;
  double wavenumber_;
  double amplitude_;
};

// --noise simplex with a rotation method (noise/rotating_gradients.hpp); throws std::invalid_argument naming the
// methods' dimension for fast and well_behaved outside 3D.
template <int N>
std::shared_ptr<const NoiseFunctions<N>> make_rotating_simplex_noise(std::uint64_t seed, double phase,
                                                                     GradientRotation rotation);

extern template class SimplexNoise<2>;
extern template class SimplexNoise<3>;
extern template class SimplexNoise<4>;
extern template class SimplexNoise<5>;
extern template class SimplexNoise<6>;
extern template class SimplexNoise<7>;
extern template class SimplexNoise<8>;

}  // namespace dfvn
