// Bridson, Hourihan and Nordenstam's procedural toolbox (2007, seed 003, Sections 2.2-2.5) on top of the
// field: octaves of noise with a power law, a modulating amplitude, viscous (no-slip) solids, moving rigid
// spheres (Eq. 6) and vortex primitives (Eqs. 7-8). All of them act on potentials, so the field stays
// exactly divergence-free:
//   --field curl (2D: the stream function psi; 3D: the vector potential psi, c = curl psi);
//   --field dfvn (any N): on f_1, the first of the N-1 functions. In 3D c = grad f_1 x grad f_2 =
//     curl (f_1 grad f_2), so modulating f_1 by A(x) is modulating that potential, and in every N the f_i
//     stay C2 functions, so c stays a cross product of gradients and reprojection stays valid.
// Bodies and vortices add potentials that are not cross products of gradients: they exist for 3D curl
// noise only (their streamlines are then not intersections of iso-surfaces, as for curl noise itself).
//
// The octaves (Section 2.2, Figure 2's psi_T = sum_i a_i ramp(d / d_i) N(x / d_i)): octave o reads an
// independently seeded instance of the basis at 2^o times the frequency, and its boundary transition
// width is w / 2^o ("each octave adjusted in a scale-appropriate way", d0 = the octave's length scale).
// Each octave's field has RMS |c| = 1 on its own; their weights are
//   a_o = g^o / sqrt(sum_{k<K} g^(2k)),   g = the octave gain (velocity ratio between successive octaves),
// so the sum has RMS |c| = 1 as every field of the library: for curl noise c = sum a_o c_o of independent
// fields (energy a_o^2 per octave, ratio g^2 from one octave to the next); for DFVN each f_i = sum a_o f_i^(o),
// whose gradient is a sum of independent isotropic gradients of energy G^2 sum a_o^2 = G^2, so E|c|^2 = 1 by
// the same Cauchy-Binet count as one octave (field/constraint.hpp, noise_gradient_rms); in 2D DFVN is curl
// noise and its energy per octave is a_o^2 too, in N >= 3 the cross product mixes the octaves.
// The default gain is Kolmogorov's: E(k) ~ k^(-5/3), so the energy in an octave [k, 2k] scales as
// k^(-2/3) and the velocity as k^(-1/3): g = 2^(-1/3) = 0.794 per halving of the length scale.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "dfvn/core/dimension.hpp"
#include "dfvn/field/constraint.hpp"
#include "dfvn/field/obstacles.hpp"

namespace dfvn {

inline const double kKolmogorovOctaveGain = 0.79370052598409973738;  // 2^(-1/3), derived above
inline constexpr int kMaxOctaves = 10;  // the top octave reads the noise 2^9 times faster (domain check)

// A moving rigid sphere (Section 2.5, Eq. 6): "sphere:CX,CY,CZ,R,VX,VY,VZ,WX,WY,WZ", centre, radius,
// linear velocity V and angular velocity W (radians per unit time about the centre).
struct RigidBody {
  Vec<3> centre = Vec<3>::Zero();
  double radius = 0.0;
  Vec<3> velocity = Vec<3>::Zero();
  Vec<3> angular = Vec<3>::Zero();
  // The blend region: the rigid potential is blended to zero between the surface and kBlendRadii radii
  // from the centre (A_b = 1 - S((r - R) / ((kBlendRadii - 1) R)), S the C2 quintic smoothstep, so A_b = 1
  // with zero slope on the surface and 0 from 2R on). A moving sphere's potential flow falls off as
  // (R / r)^3, 1/8 at 2R. Eq. 6's reference level is the blend radius, so the blended rotation term
  // w (R_b^2 - r^2) / 2 falls monotonically to zero, as the paper asks.
  static constexpr double kBlendRadii = 2.0;
  double blend_radius() const { return kBlendRadii * radius; }
};
RigidBody parse_body(std::string_view spec);  // throws std::invalid_argument naming what is wrong
std::string to_string(const RigidBody& body);

// Vortex primitives (Section 2.5) with the fall-off f(s) = 1 - S(s), s = distance / R, S the C2 quintic
// smoothstep: f(0) = 1, f(1) = f'(1) = f''(1) = 0, so the potential and its first two derivatives vanish
// at the core radius R and beyond.
//   particle:CX,CY,CZ,WX,WY,WZ,R   Eq. 7: psi = f(|x - x0| / R) w (R^2 - |x - x0|^2) / 2; near the centre
//                                  c = w x (x - x0), a rigid rotation at angular velocity W.
//   ring:CX,CY,CZ,NX,NY,NZ,RR,W,R  Eq. 8 over the circle of radius RR about the centre in the plane normal
//                                  to N: psi = f(rho / R) W t(x) (R^2 - rho^2) / 2, rho the distance to the
//                                  circle, t the circle's unit tangent n x p / |p| at the closest point
//                                  (p = x's offset from the centre in the plane), W the angular velocity
//                                  about the core; R < RR, so the tube never reaches the axis where t jumps.
//                                  A positive W turns the fluid inside the ring along +N.
struct Vortex {
  enum class Kind { particle, ring } kind = Kind::particle;
  Vec<3> centre = Vec<3>::Zero();
  Vec<3> omega = Vec<3>::Zero();   // particle: the angular velocity vector W
  Vec<3> normal = Vec<3>::Zero();  // ring: the unit normal N
  double ring_radius = 0.0;        // ring: RR
  double strength = 0.0;           // ring: W
  double core_radius = 0.0;        // R
};
Vortex parse_vortex(std::string_view spec);  // throws std::invalid_argument naming what is wrong
std::string to_string(const Vortex& vortex);

// The amplitude A(x) that modulates the (turbulent) potential, psi -> A psi (Section 2.3), a product of
// these shapes (each C2):
//   constant:A       A, any finite real;
//   height:Z0,Z1     S((x_N - Z0) / (Z1 - Z0)): 0 below Z0 and 1 beyond Z1 along the last coordinate (a
//                    column of smoke), Z0 != Z1 (Z1 < Z0 turns it over);
//   obstacles:D      1 - prod_b S(d_b / D) over the obstacles and bodies b (d_b the distance to b's surface):
//                    1 on every solid, 0 once every one is at least D away ("zero away from obstacles").
struct AmplitudeShape {
  enum class Kind { constant, height, obstacles } kind = Kind::constant;
  std::vector<double> parameters;
};
AmplitudeShape parse_amplitude(std::string_view spec);  // throws std::invalid_argument
std::string to_string(const AmplitudeShape& shape);

struct FlowOptions {
  int octaves = 1;                              // K in [1, kMaxOctaves]
  double octave_gain = kKolmogorovOctaveGain;   // g in (0, 1]... any finite positive value
  std::vector<AmplitudeShape> amplitude;        // their product; none: A = 1
  // No-slip solids (Section 2.4): the potential times V(x) = prod_b S(d_b / w) over the domain's wall and
  // every obstacle and body (w the transition width): V and grad V vanish on every solid, so every first
  // derivative of V psi does and c = 0 there (on a moving body c is then its rigid motion: the body's
  // own potential is added after V, with a blend of zero slope on the surface).
  bool viscous = false;
  std::vector<RigidBody> bodies;
  std::vector<Vortex> vortices;

  bool active() const {
    return octaves != 1 || !amplitude.empty() || viscous || !bodies.empty() || !vortices.empty();
  }
  // Throws std::invalid_argument for octaves outside [1, kMaxOctaves] or a gain that is not finite and
  // positive (the rest is checked by the parsers and, against the field, by check_flow).
  void validate() const;
};

// a_o for o = 0..K-1 (the header's formula).
std::vector<double> octave_weights(int octaves, double gain);

// The bodies as obstacles (spheres of their radius), for the boundary terms that treat every solid alike.
std::vector<Obstacle> body_obstacles(const std::vector<RigidBody>& bodies);

// Throws std::invalid_argument with one line where the flow does not fit the field: bodies and vortices
// need 3D curl noise, bodies and --viscous a domain (cube or ball), amplitude obstacles:D an obstacle or a
// body; each body's blend region must lie inside the domain clear of its wall's zone (as an obstacle of
// radius R_b, check_obstacles) and of every other solid's.
void check_flow(const FlowOptions& flow, int dimension, bool curl, FieldConstraint domain,
                const std::vector<Obstacle>& obstacles, double width);

// A(x) and its gradient (1 and 0 without shapes). `solids`: the obstacles and the bodies.
template <int N>
double flow_amplitude(const std::vector<AmplitudeShape>& shapes, const std::vector<Obstacle>& solids, const Vec<N>& x,
                      Vec<N>& gradient);

// V(x) = prod over the domain's wall (its boundary function: the cube's H or the ball's distance) and the
// solids of S(d / w), and its gradient.
template <int N>
double viscous_factor(FieldConstraint domain, const std::vector<Obstacle>& solids, double width, const Vec<N>& x,
                      Vec<N>& gradient);

// The blended rigid potential A_b(x) psi_rigid(x) of Eq. 6 with psi_rigid = V x r / 2 + w (R_b^2 - |r|^2) / 2,
// r = x - centre (Eq. 6 as printed has V x r, whose curl is 2V: half of it moves the body at V), added to
// psi with its Jacobian rows added to jacobian (jacobian[i] = grad psi_i).
void add_body_potential(const RigidBody& body, const Vec<3>& x, std::array<double, 3>& psi,
                        std::array<Vec<3>, 3>& jacobian);
// The vortex's potential added likewise (zero beyond its core radius).
void add_vortex_potential(const Vortex& vortex, const Vec<3>& x, std::array<double, 3>& psi,
                          std::array<Vec<3>, 3>& jacobian);

}  // namespace dfvn
