// Spherical obstacles inside the cube or the ball (--obstacle sphere:CX,CY[,CZ...],R), and Bridson,
// Hourihan and Nordenstam's (2007, seed 003, Sections 3-4) boundary treatment of 3D curl noise.
//
// Every boundary b (the domain's and each obstacle's) has a distance-like function d_b, positive in the
// fluid, zero on the boundary, with gradient n_b normal to it there, and a transition zone d_b < w (w the
// constraint's transition width, Bridson's d0):
//   cube: the harmonic-mean boundary function H of constraint.hpp (smooth inside; |grad H| = 1 on a face
//     away from its edges, smaller near them: only its direction matters on the boundary);
//   ball: 1/2 - |x - centre|;  obstacle: |x - c| - R.
// The zones must be disjoint (check_obstacles refuses obstacles that overlap each other or the domain's
// zone), so near each boundary only its own term acts.
//   DFVN (any N) and 2D curl noise: f_1 (in 2D the stream function) times ramp(d_b / w) for each obstacle
//     (after the domain's --bound), Bridson's ramped stream function: C2, zero on the obstacle, gradient
//     normal to it, so c is tangent there and a reprojected trace keeps f_1 at its start value, which the
//     obstacle's f_1 = 0 cannot meet.
//   3D curl noise: psi_c = alpha psi + (1 - alpha) n (n . psi), alpha = |ramp(d / w)|, applied per
//     boundary. On the boundary alpha = 0, so psi_c's tangential part vanishes on the whole surface and
//     (curl psi_c) . n, which holds only tangential derivatives of it, is 0.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "dfvn/core/dimension.hpp"
#include "dfvn/field/constraint.hpp"

namespace dfvn {

struct Obstacle {
  std::vector<double> centre;  // N coordinates
  double radius = 0.0;
};

// "sphere:CX,CY[,CZ...],R" -> an obstacle; throws std::invalid_argument naming what is wrong (the shape,
// a number, R <= 0, NaN or infinite values). The arity is checked against N by check_obstacles.
Obstacle parse_obstacle(std::string_view spec);
std::string to_string(const Obstacle& obstacle);

// Throws std::invalid_argument unless every obstacle has N centre coordinates and R > 0, the domain is the
// cube or the ball, each obstacle with its zone (R + w) lies inside the domain away from the domain's zone
// (cube: every face at least R + sqrt(2N) w from the centre, since H >= min face distance / sqrt(2N);
// ball: |c - centre| + R + 2 w <= 1/2), and no two obstacles' zones meet (|c_a - c_b| >= R_a + R_b + 2 w).
void check_obstacles(int dimension, FieldConstraint domain, const std::vector<Obstacle>& obstacles, double width);

// |x - c| - R and its gradient (the unit vector from c; zero at c).
template <int N>
double obstacle_distance(const Obstacle& obstacle, const Vec<N>& x, Vec<N>& gradient);

// Whether x lies outside (or on) every obstacle.
template <int N>
bool outside_obstacles(const std::vector<Obstacle>& obstacles, const Vec<N>& x);

// f_1 and its gradient times ramp(d_b / w) for each obstacle whose zone holds x.
template <int N>
void ramp_obstacles(const std::vector<Obstacle>& obstacles, double width, const Vec<N>& x, double& value, Vec<N>& gradient);

// Bridson's 3D boundary on the potential (psi, its Jacobian rows jacobian[i] = grad psi_i): the domain's
// (inside_cube or inside_ball; none skips it) and each obstacle's, in place.
void bridson_boundary_3d(FieldConstraint domain, const std::vector<Obstacle>& obstacles, double width, const Vec<3>& x,
                         std::array<double, 3>& psi, std::array<Vec<3>, 3>& jacobian);

}  // namespace dfvn
