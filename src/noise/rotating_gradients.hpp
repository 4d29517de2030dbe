// McEwan and Gustavson's three ways to make a rotating gradient in 3D (seed 001, "Rotating noise vectors: the
// full story"): the policy that simplex noise's corner gradients turn with the phase alpha (--rotation).
//   two_vector: the document's Section 2 and the library's method in every dimension and basis: p hashed from
//     the basis's own gradient set, q a second gradient of the set made orthogonal to p and as long,
//     g = p cos alpha + q sin alpha (noise/simplex_noise.hpp). Phase 0 is the basis's own noise.
//   fast (Section 3 / 5.2): one hash k in Z_289 gives the rotation axis r = fib(k) on the Fibonacci sphere and an
//     angle psi(k); q' = r x n / |r x n| and p' = q' x r span the plane normal to r (n = (0, 0, 1)),
//     g = p' cos(alpha - psi) + q' sin(alpha - psi). No alpha gives back a static gradient set.
//   well_behaved (Section 4 / 5.3, the document's default): p = fib(k) and q' = (sin psi, cos psi, 0) on the
//     equator, q = q' rotated by the rotation taking n to p (Rodrigues, in the document's closed form),
//     g = p cos alpha + q sin alpha. At alpha = 0 it is exactly fib(k), the no-rotation noise of Section 5.1,
//     which the noise takes as its shortcut (g = p, bit for bit the full formula at cos = 1, sin = 0).
// The Fibonacci mapping (Section 5) with the document's constants, for k = 0..288 (289 = 17^2, the modulus of its
// permutation polynomial):
//   theta = (2 pi / phi) k mod 2 pi (phi the golden ratio),  cos(phi_k) = -2k/289 + 1 - 1/289,
//   psi = (10 pi / 289) k mod 2 pi,
//   fib(k) = (cos theta sin phi_k, sin theta sin phi_k, cos phi_k): 289 points of equal area on the sphere.
// The document's hash is P(P(P(u) + v) + w) for an unstated P; here k is the library's 64-bit corner hash modulo 289
// (its bias, 2^64 mod 289 / 2^64, is below 1e-16). Its gradients are unit vectors; simplex noise scales them by
// sqrt(2), the length of its own 3D gradients (the edge midpoints of the cube), so E|g|^2 and with it the
// normalisation are those of the basis (data/rotation_methods.md measures RMS |c|, the correlation against alpha
// and the cost of the three).
// Only 3D: the fast method crosses the axis with the pole and both read the 3D Fibonacci sphere; the two-vector
// method is the one that generalises (it is the library's in every dimension).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <string_view>

namespace dfvn {

enum class GradientRotation { two_vector, fast, well_behaved };
inline constexpr GradientRotation kDefaultGradientRotation = GradientRotation::two_vector;
inline constexpr GradientRotation kAllGradientRotations[] = {GradientRotation::two_vector, GradientRotation::fast,
                                                             GradientRotation::well_behaved};
GradientRotation parse_gradient_rotation(std::string_view name);  // throws std::invalid_argument listing the names
std::string_view to_string(GradientRotation rotation);
std::string gradient_rotation_names();  // "two-vector, fast, well-behaved"

inline constexpr int kFibonacciPoints = 289;

// The Fibonacci mapping's angles of k: cos/sin theta, cos/sin phi_k, cos/sin psi.
struct FibonacciAngles {
  double cos_theta, sin_theta, cos_phi, sin_phi, cos_psi, sin_psi;
};
inline FibonacciAngles fibonacci_angles(int k) {
  constexpr double kTwoPiOverGolden = 2.0 * std::numbers::pi / std::numbers::phi;  // a_1 = 2 pi / phi
  constexpr double kPsiStep = 10.0 * std::numbers::pi / kFibonacciPoints;           // a_2 = 10 pi / 289, c_2 = 0
  constexpr double kCosPhiStep = -2.0 / kFibonacciPoints;                            // a_3 = -2 / 289
  constexpr double kCosPhiStart = 1.0 - 1.0 / kFibonacciPoints;                      // c_3 = 1 - 1 / 289
  const double theta = std::fmod(kTwoPiOverGolden * k, 2.0 * std::numbers::pi);
  const double psi = std::fmod(kPsiStep * k, 2.0 * std::numbers::pi);
  const double cos_phi = kCosPhiStep * k + kCosPhiStart;  // in [-288/289, 288/289] for k < 289: no wrap needed
  return {std::cos(theta), std::sin(theta), cos_phi, std::sqrt(1.0 - cos_phi * cos_phi), std::cos(psi), std::sin(psi)};
}

// fib(k): the no-rotation gradient (Section 5.1).
inline std::array<double, 3> fibonacci_gradient(const FibonacciAngles& a) {
  return {a.cos_theta * a.sin_phi, a.sin_theta * a.sin_phi, a.cos_phi};
}

// The fast method's g at alpha, from cos/sin alpha (Section 5.2, expanded): with d = alpha - psi,
// q' = (sin theta, -cos theta, 0), p' = (-cos phi cos theta, -cos phi sin theta, sin phi).
inline std::array<double, 3> fast_rotating_gradient(const FibonacciAngles& a, double cos_alpha, double sin_alpha) {
  const double c = cos_alpha * a.cos_psi + sin_alpha * a.sin_psi;  // cos(alpha - psi)
  const double s = sin_alpha * a.cos_psi - cos_alpha * a.sin_psi;  // sin(alpha - psi)
  return {-a.cos_phi * a.cos_theta * c + a.sin_theta * s, -a.cos_phi * a.sin_theta * c - a.cos_theta * s, a.sin_phi * c};
}

// The well-behaved method's q (Section 5.3's closed form): m = (sin psi sin theta - cos psi cos theta)(1 - cos phi),
// q = (sin psi cos phi + sin theta m, cos psi cos phi - cos theta m, -(p_y cos psi + p_x sin psi)).
inline std::array<double, 3> well_behaved_second_vector(const FibonacciAngles& a) {
  const std::array<double, 3> p = fibonacci_gradient(a);
  const double m = (a.sin_psi * a.sin_theta - a.cos_psi * a.cos_theta) * (1.0 - a.cos_phi);
  return {a.sin_psi * a.cos_phi + a.sin_theta * m, a.cos_psi * a.cos_phi - a.cos_theta * m,
          -(p[1] * a.cos_psi + p[0] * a.sin_psi)};
}

// g = p cos alpha + q sin alpha.
inline std::array<double, 3> well_behaved_rotating_gradient(const FibonacciAngles& a, double cos_alpha, double sin_alpha) {
  const std::array<double, 3> p = fibonacci_gradient(a), q = well_behaved_second_vector(a);
  return {p[0] * cos_alpha + q[0] * sin_alpha, p[1] * cos_alpha + q[1] * sin_alpha, p[2] * cos_alpha + q[2] * sin_alpha};
}

}  // namespace dfvn
