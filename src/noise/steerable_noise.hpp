// Steerable noise (seed 002, Rice, "Steerable Perlin Noise", supplement): lattice gradient noise whose
// corner terms are read through a metric tensor G that is short along a direction u, so the noise is
// elongated along u. 2D to 4D (issue 27 item 3; data/steerable_notes.md lists the document's defects
// and the numbers measured here).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dfvn/core/dimension.hpp"
#include "dfvn/noise/gradient_noise.hpp"
#include "dfvn/noise/noise_functions.hpp"

namespace dfvn {

inline constexpr int kMaxSteerableDimension = 4;
inline constexpr double kDefaultSteerK = 0.5;      // the document's k (its demos)
inline constexpr double kSteerEpsilon = 1e-4;      // the document's epsilon
inline constexpr double kSteerCircularCore = 1.0;  // the circular field's core radius, in lattice cells

// A 2D direction field read from an image or an array (--steer-image, Figure 3's image-driven field), over the
// unit square of the field's coordinates: per pixel the tensor T = u u^T of its unit direction u (T = I / 2
// where u = 0: no direction), stored as (T_xx, T_xy, T_yy). Pixel (i, j) sits at x = j / (columns - 1),
// y = i / (rows - 1) (rows, columns >= 2). The noise reads H(x), the uniform cubic B-spline of the tensors (not
// interpolating: its weights are >= 0 and sum to 1, so H is a convex combination of unit rank-one tensors,
// symmetric with trace 1 and eigenvalues in [0, 1]), C2 everywhere; beyond the square its control points
// continue as the border's.
struct DirectionGrid {
  int rows = 0, columns = 0;
  std::vector<std::array<double, 3>> tensors;  // rows x columns, pixel (i, j) at i * columns + j
  std::string source;                          // the file it was read from (for messages and records)
};

// Which direction field steers the noise: a constant direction (any non-zero length: G discards |u|), the
// document's circular field u(y) = (-y_2, y_1, 0, ...) around the origin (Figure 2) or, in 2D, an image's
// (Figure 3).
struct SteerSpec {
  std::vector<double> direction;  // the constant direction U; empty with `circular` or `image`
  double k = kDefaultSteerK;
  bool circular = false;
  std::shared_ptr<const DirectionGrid> image;  // --steer-image (2D)
  // The image's unit square in the basis's units: y = image_scale x. Set by the field (2 pi F / k_eff of the
  // same noise steered by a constant direction, whose k_eff and amplitude the image-steered noise reports, so
  // that the field's own scale s maps the image onto [0, 1]^2 exactly); 0 until then.
  double image_frequency = 0.0;  // the field's F, which the noise turns into image_scale
  // The document's Section 2 "quality" Q in 0..N: the corners run from -Q to Q + 1 along each axis ((2Q + 2)^N of
  // them), the smallest eigenvalue k becomes k / (Q + 1) and the Perlin weights read v / (Q + 1) (its
  // 2 / (|start| + |end| + 1)); Q = 0 is the single-order noise. (The text's loop -(Q - 1)..Q is empty at
  // Q = 0 and disagrees with its own code's -Q..Q + 1, which we follow: data/steerable_notes.md.)
  int quality = 0;
  bool active() const { return !direction.empty() || circular || image != nullptr; }
};

// Throws std::invalid_argument with one line unless the spec is usable in `dimension`: 2 <= N <= 4, exactly
// one of a direction (N finite components, not all 0), the circular field and an image (2D only), 0 < k <= 1
// with k below (4 - (N-1) eps) / N (so that the remapped eigenvalue along u is the smallest one: k = 1 in 4D is
// refused), and the quality in 0..N.
void check_steer_spec(const SteerSpec& spec, int dimension);

// H(x) of the grid at x (field coordinates) and, if asked, dH/dx_1 and dH/dx_2, each as (xx, xy, yy).
std::array<double, 3> direction_tensor(const DirectionGrid& grid, const Vec<2>& x,
                                       std::array<std::array<double, 3>, 2>* gradient = nullptr);

// The document's metric (Section 1.1): the eigenvalues of H = u u^T, |u|^2 along u and 0 across it, are
// remapped linearly to mu = k along u and a = (4 - k) / (N - 1) - eps across it:
//   G = a I + (k - a) u u^T / |u|^2,   tr G = 4 - (N - 1) eps < 4.
template <int N>
Eigen::Matrix<double, N, N> steer_metric(const Vec<N>& unit_direction, double k);

// n_i(y) = sum over the 2^N corners b of the lattice cell of z = R_i y + o_i (the quintic gradient
// basis's rotations, offsets and hashed gradients g, noise/gradient_noise.hpp, so the phase turns them the
// same way) of the document's single-octave term (its Section 5.2):
//   (g_w . G v_w) * P(v) * phi(v_w^T G v_w),   v = b - frac(z) (lattice frame), v_w = R_i^T v, g_w = R_i^T g,
//   P(v) = prod_j phi(|v_j|) (the Perlin weights),   phi(t) = 1 - s(t) on [0, 1], 0 beyond,
// with s the quintic fade 6t^5 - 15t^4 + 10t^3. The document leaves `interp` undefined; phi is the
// polynomial of lowest degree with phi(0) = 1, phi'(0) = phi''(0) = 0 and value, first and second
// derivative 0 at 1: it makes P exactly the quintic basis's weights (a partition of unity over the
// corners), and each term is C2 (phi(|t|) is C2 at 0 since phi'(0) = phi''(0) = 0; phi(q) is C2 at q = 1), so
// n_i is C2 and the DFVN field of these functions is exactly divergence-free.
// G is in world coordinates (u does not turn with the lattice of function i): the terms above are
// G-products of world vectors. Not normalised by the weight sum (the document's code does not divide
// either); the weight sum sum_b P phi stays > 0 because tr G < 4 (weight_sum; data/steerable_notes.md).
// With the circular field, G varies with y:
//   G(y) = c(y) I + (k - a) u u^T / (r^2 + d^2),  c(y) = g0 + (a - g0) r^2 / (r^2 + d^2),  g0 = (4 - (N-1) eps) / N,
// r = |u| = |(y_1, y_2)|, d = kSteerCircularCore: the document's G away from the axis (r >> d), the
// isotropic metric of the same trace on it (where u = 0 has no direction), smooth (rational) in between,
// with tr G = 4 - (N - 1) eps everywhere. The gradient includes the terms of dG/dy.
// With an image (2D): G(y) = a I + (k - a) H(y / image_scale), H the direction tensors' B-spline (DirectionGrid):
// where the image has one direction u, H = u u^T and G is the document's metric; where its directions disagree
// H tends to I / 2 and G to the isotropic metric of the same trace (tr G = a + k = 4 - eps everywhere); dG/dy
// comes from the B-spline's derivative, so the gradient is analytic. Its k_eff and amplitude are those of the same
// noise steered by the constant direction (1, 0), measured as below (the local statistics of a turned lattice).
// With quality Q (SteerSpec::quality): the corners -Q..Q+1 per axis, k / (Q + 1) for k, weights P(v / (Q + 1)).
// wavenumber() and amplitude() are measured per instance (seed, phase, spec) over 2^15 points of a
// Kronecker sequence in the box [-32, 32)^N of the basis's units (centred on the circular field's axis):
// E n^2, E|grad n|^2 and E|cross(grad n_i)|^2, so RMS |c| = 1 as for every basis.
template <int N>
class SteerableNoise final : public NoiseFunctions<N> {
 public:
  static_assert(N >= 2 && N <= kMaxSteerableDimension);
  using Matrix = Eigen::Matrix<double, N, N>;

  // Throws std::invalid_argument (check_steer_spec) for a bad spec.
  SteerableNoise(std::uint64_t seed, double phase, const SteerSpec& spec);

  NoiseSample<N, N - 1> evaluate(const Vec<N>& y) const override;
  double wavenumber() const override { return wavenumber_; }
  double amplitude() const override { return amplitude_; }

  // G at y and its partial derivatives dG/dy_j (all 0 for a constant direction).
  Matrix metric(const Vec<N>& y, std::array<Matrix, N>* derivatives = nullptr) const;
  // The weight sum sum_b P(v) phi(v^T G v) of function i at y: > 0 everywhere when tr G < 4.
  double weight_sum(int function, const Vec<N>& y) const;
  const QuinticGradientNoise<N>& lattice() const { return lattice_; }
  double remapped_across() const { return across_; }  // a = (4 - k) / (N - 1) - eps

 private:
  // The measurement of k_eff and the amplitude (the constructor's loop over Kronecker points).
  void measure();
  QuinticGradientNoise<N> lattice_;
  SteerSpec spec_;
  int side_ = 2;                 // corners per axis, 2Q + 2
  int corners_ = 1 << N;         // side_^N
  double weight_scale_ = 1.0;    // the Perlin weights read v / (Q + 1)
  double steer_k_ = kDefaultSteerK;  // k / (Q + 1)
  double image_scale_ = 0.0;     // y = image_scale_ x for the image
  Vec<N> u_ = Vec<N>::Zero();  // the constant unit direction
  Matrix constant_metric_ = Matrix::Identity();
  double across_ = 0.0, isotropic_ = 0.0;
  double wavenumber_ = 0.0, amplitude_ = 0.0;
};

// The steerable basis in dimension N: SteerableNoise<N> for 2 <= N <= 4; throws std::invalid_argument
// (check_steer_spec's line) in higher dimensions and for a bad spec.
template <int N>
std::shared_ptr<const NoiseFunctions<N>> make_steerable_noise(std::uint64_t seed, double phase, const SteerSpec& spec);

extern template class SteerableNoise<2>;
extern template class SteerableNoise<3>;
extern template class SteerableNoise<4>;

}  // namespace dfvn
