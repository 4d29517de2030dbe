// Replacing the first of the N-1 functions by a geometric one (Section 4): "DFVN bounded by
// (hyper)surfaces" (Eq. 13) keeps every trace inside a domain, "DFVN on (hyper)surfaces" keeps every
// trace on a hypersurface. c = cross(grad f_1, ..., grad f_{N-1}) stays divergence-free because every
// f_i stays C2, and Algorithm 1's reprojection holds f_1 at its start value like any other f_i.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "dfvn/core/dimension.hpp"

namespace dfvn {

// none: the free field. inside_cube: [0,1]^N. inside_ball: the cube's inscribed ball, centre
// (1/2, ..., 1/2), radius 1/2. on_sphere: the unit sphere |x| = 1 (N >= 3).
enum class FieldConstraint { none, inside_cube, inside_ball, on_sphere };
std::string_view to_string(FieldConstraint constraint);

// How f_1 turns into the boundary function d near the boundary of the cube or the ball: a policy chosen
// once (FieldOptions::bound). Both make the boundary a level set of a C2 f_1 whose gradient is normal
// to it, so c is tangent there and no trace leaves; they differ in how they slow the motion normal to
// the boundary (data/boundary_shares.md measures both).
//   eq13: the paper's Eq. (13), f_1 = (1 - alpha) G d + alpha f~_1: f_1 ~ G d near the boundary, so a
//     point keeps its distance to it.
//   ramp: Bridson et al. 2007's (seed 003, Section 3), f_1 = ramp(d / w) f~_1 with
//     ramp(r) = (15 r - 10 r^3 + 3 r^5) / 8 on [0, 1] (odd, 1 beyond): the noise scaled down to 0 on
//     the boundary, which keeps its level sets' shape but squeezes them against the boundary.
enum class Bound { eq13, ramp };
inline constexpr Bound kAllBounds[] = {Bound::eq13, Bound::ramp};
Bound parse_bound(std::string_view name);  // throws std::invalid_argument listing the names
std::string_view to_string(Bound bound);
std::string bound_names();  // "eq13, ramp"

// The RMS gradient G of each noise function of the field. N-1 independent isotropic gradients with
// E|grad f_i|^2 = G^2 have E|cross|^2 = N! (G^2 / N)^(N-1) (Cauchy-Binet: N minors of size N-1, each
// with (N-1)! surviving permutation terms of expectation (G^2/N)^(N-1)), and the field is normalised
// to RMS |cross| = 1 (field/dfvn_field.hpp), so G^2 = N / (N!)^(1/(N-1)): 1 in 2D, 1.22 in 3D, 1.69
// in 7D. The geometric functions below have this gradient on their boundary, so points move there
// about as fast as inside.
double noise_gradient_rms(int dimension);

// The C2 quintic smoothstep S(u) = 6u^5 - 15u^4 + 10u^3 on [0, 1], 0 below and 1 above; S'(0) =
// S'(1) = S''(0) = S''(1) = 0, so S is C2 on the whole line.
double smoothstep_c2(double u, double* derivative);

// Bridson's ramp (15 r - 10 r^3 + 3 r^5) / 8 for |r| < 1, sign(r) beyond: odd, C2 (its first and second
// derivatives vanish at |r| = 1), slope 15/8 at 0.
double bridson_ramp(double r, double* derivative);

// The cube's boundary function H (value and gradient), in length units. Inside the open cube, with
// t_k the distances to the 2N faces (x_j and 1 - x_j),
//   H(x) = (sum_k t_k^-2)^(-1/2),
// a harmonic mean that is C-infinity in the open cube, positive inside, -> 0 on the boundary and
// <= min_k t_k, with grad H -> the inward normal on a face away from its edges. The cube's distance
// function min_k t_k is not C2 on its medial axis, which reaches into every edge; H is smooth
// everywhere inside and only its continuous extension to the boundary is non-smooth, at the edges
// and corners themselves, which no trace reaches (a level set H = h lies in [h, 1-h]^N).
// Consequence near edges and corners: the level sets H = h are cubes whose edges are rounded over
// a length ~h, so a point near an edge slides around it on a rounded surface instead of running into
// it; near k faces at equal distance t, H = t / sqrt(k) and |grad H| = 1 / k, so the boundary
// function's share of the field is k times slower there (never zero, unlike a C2 function that is
// zero exactly on the cube's boundary, whose gradient must vanish on every edge).
// Outside the cube (or on it) H is the most negative face distance, continuous with the inside.
template <int N>
double cube_boundary_function(const Vec<N>& x, Vec<N>& gradient);

// The signed distance to the inscribed ball's sphere, positive inside; C-infinity except at the
// centre (its medial axis).
template <int N>
double ball_boundary_function(const Vec<N>& x, Vec<N>& gradient);

// Whether x lies in the closed domain of the constraint (every x for none; |x| = 1 within
// `sphere_tolerance` for on_sphere).
template <int N>
bool satisfies_constraint(FieldConstraint constraint, const Vec<N>& x, double sphere_tolerance = 1e-12);

// f_1 of the constrained field from the noise function f~_1 it replaces.
//   inside_cube, inside_ball with Bound::eq13: Eq. (13), f_1 = (1 - alpha) G d + alpha f~_1, with d the
//     boundary function above and alpha C2, 0 on (and outside) the boundary and 1 deeper than the
//     transition width w: cube alpha = prod_k S(t_k / w), ball alpha = S(d / w). On the boundary
//     alpha = 0 and grad alpha = 0, so grad f_1 = G grad d is normal to it and c, orthogonal to
//     grad f_1, is tangent: no trace can leave.
//   inside_cube, inside_ball with Bound::ramp: f_1 = ramp(d / w) f~_1 (bridson_ramp), untouched where
//     d >= w. On the boundary f_1 = 0 and grad f_1 = (15 / 8w) f~_1 grad d is normal to it (or zero).
//   on_sphere: f_1 = (G / 2) |x|^2 (the noise is not used), so c is tangent to every sphere |x| = r.
template <int N>
class ConstraintFunction {
 public:
  // Throws std::invalid_argument if transition_width is not in (0, 1/4] for inside_cube and
  // inside_ball (the cube's half-width and the ball's radius are 1/2: w <= 1/4 leaves a core where
  // alpha = 1), or if the constraint is none or on_sphere in 2D (a circle's field has no noise left).
  ConstraintFunction(FieldConstraint constraint, double transition_width, Bound bound = Bound::eq13);

  // Replaces (value, gradient) = (f~_1(x), grad f~_1(x)) by (f_1(x), grad f_1(x)).
  void replace(const Vec<N>& x, double& value, Vec<N>& gradient) const;

  FieldConstraint constraint() const { return constraint_; }
  double transition_width() const { return width_; }
  Bound bound() const { return bound_; }

 private:
  FieldConstraint constraint_;
  double width_;
  Bound bound_;
  double gradient_rms_;  // G
  // The (constraint, bound) policy, chosen once in the constructor.
  using Replacement = void (*)(const ConstraintFunction&, const Vec<N>&, double&, Vec<N>&);
  Replacement replace_;
  static Replacement choose_replacement(FieldConstraint constraint, Bound bound);
};

}  // namespace dfvn
