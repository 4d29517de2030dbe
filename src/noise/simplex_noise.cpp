#include "dfvn/noise/simplex_noise.hpp"

#include <cassert>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/hash.hpp"
#include "dfvn/core/message_text.hpp"
#include "dfvn/noise/simplex_normalisation.hpp"

namespace dfvn {
namespace {

// Gradient directions. For N >= 3 the midpoints of the edges of the cube [-1,1]^N (one coordinate
// zero, the others +-1: N 2^(N-1) directions), the set Perlin and Gustavson use in 3D and 4D.
// In 2D that set has only the 4 axis directions, so 2D uses 8 directions 45 degrees apart instead.
template <int N>
inline void gradient_from_hash(std::uint64_t h, double* g) {
  if constexpr (N == 2) {
    static constexpr double kDiagonal = 0.70710678118654752440;  // 1/sqrt(2)
    static constexpr double kDirections[8][2] = {{1, 0},
                                                 {kDiagonal, kDiagonal},
                                                 {0, 1},
                                                 {-kDiagonal, kDiagonal},
                                                 {-1, 0},
                                                 {-kDiagonal, -kDiagonal},
                                                 {0, -1},
                                                 {kDiagonal, -kDiagonal}};
    const auto k = static_cast<int>(h >> 61);
    g[0] = kDirections[k][0];
    g[1] = kDirections[k][1];
  } else {
    const auto zero_axis = static_cast<int>((h >> 32) % static_cast<std::uint64_t>(N));
    for (int j = 0; j < N; ++j) g[j] = ((h >> j) & 1U) ? -1.0 : 1.0;
    g[zero_axis] = 0.0;
  }
}

// The corner gradient at a phase (the header): p from the hash h, q from re-mixed hashes of the same
// set until it is not parallel to p (for N >= 3 the axis where p is zero gives one if 16 draws did not).
template <int N>
inline void rotated_gradient_from_hash(std::uint64_t h, double cos_phase, double sin_phase, double* g) {
  double p[N], q[N];
  gradient_from_hash<N>(h, p);
  double p2 = 0.0;
  for (int j = 0; j < N; ++j) p2 += p[j] * p[j];
  double q2 = 0.0;
  std::uint64_t k = h;
  for (int attempt = 0; attempt < 17; ++attempt) {
    if (attempt < 16) {
      k = mix64(k + kGoldenGamma);
      gradient_from_hash<N>(k, q);
    } else if constexpr (N == 2) {  // p turned by 90 degrees
      q[0] = -p[1];
      q[1] = p[0];
    } else {
      for (int j = 0; j < N; ++j) q[j] = p[j] == 0.0 ? 1.0 : 0.0;
    }
    double qp = 0.0;
    for (int j = 0; j < N; ++j) qp += q[j] * p[j];
    for (int j = 0; j < N; ++j) q[j] -= (qp / p2) * p[j];
    q2 = 0.0;
    for (int j = 0; j < N; ++j) q2 += q[j] * q[j];
    if (q2 > 1e-12 * p2) break;
  }
  const double scale = sin_phase * std::sqrt(p2 / q2);
  for (int j = 0; j < N; ++j) g[j] = cos_phase * p[j] + scale * q[j];
}

}  // namespace

// Odd constants for the vertex hash: the SplitMix64 outputs (mix64 of consecutive golden-ratio
// multiples), forced odd, so that each axis scrambles differently.
constexpr std::array<std::uint64_t, kMaxDimension> make_axis_multipliers() {
  std::array<std::uint64_t, kMaxDimension> k{};
  for (int j = 0; j < kMaxDimension; ++j) k[j] = mix64(kGoldenGamma * static_cast<std::uint64_t>(j + 1)) | 1U;
  return k;
}
inline constexpr std::array<std::uint64_t, kMaxDimension> kAxisMultipliers = make_axis_multipliers();

GradientRotation parse_gradient_rotation(std::string_view name) {
  for (GradientRotation r : kAllGradientRotations)
    if (name == to_string(r)) return r;
  throw std::invalid_argument("unknown rotation " + quote_for_message(name) + " (allowed: " + gradient_rotation_names() + ")");
}

std::string_view to_string(GradientRotation rotation) {
  switch (rotation) {
    case GradientRotation::two_vector: return "two-vector";
    case GradientRotation::fast: return "fast";
    case GradientRotation::well_behaved: return "well-behaved";
  }
  return "?";
}

std::string gradient_rotation_names() {
  std::string names;
  for (GradientRotation r : kAllGradientRotations) names += (names.empty() ? "" : ", ") + std::string(to_string(r));
  return names;
}

namespace {

// Seed 001's unit gradients scaled to the length of simplex noise's own 3D gradients, |(1, 1, 0)| = sqrt(2).
constexpr double kSqrt2 = 1.41421356237309504880;

void scaled(const std::array<double, 3>& u, double* g) {
  for (int j = 0; j < 3; ++j) g[j] = kSqrt2 * u[j];
}

}  // namespace

template <int N>
SimplexNoise<N>::SimplexNoise(std::uint64_t seed, double phase, GradientRotation rotation)
    : seed_(seed),
      phase_(phase),
      cos_phase_(std::cos(phase)),
      sin_phase_(std::sin(phase)),
      rotation_(rotation),
      seed_hash_(mix64(seed ^ static_cast<std::uint64_t>(Stream::noise))) {
  parse_gradient_rotation(to_string(rotation));  // an unknown enum value throws
  if (rotation != GradientRotation::two_vector && N != 3)
    throw std::invalid_argument(fmt::format(
        "--rotation {} is seed 001's 3D construction (the Fibonacci sphere, a cross product with the pole): simplex noise "
        "in 3D only; in {}D the phase turns the gradients by two-vector",
        to_string(rotation), N));
  if constexpr (N == 3) {
    if (rotation == GradientRotation::fast) {
      corner_gradient_ = [](const SimplexNoise& s, std::uint64_t h, double* g) {
        scaled(fast_rotating_gradient(fibonacci_angles(static_cast<int>(h % kFibonacciPoints)), s.cos_phase_, s.sin_phase_), g);
      };
      return;
    }
    if (rotation == GradientRotation::well_behaved) {
      if (phase == 0.0)  // Section 5.1's shortcut: g = p, the full formula's bits at cos = 1, sin = 0
        corner_gradient_ = [](const SimplexNoise&, std::uint64_t h, double* g) {
          scaled(fibonacci_gradient(fibonacci_angles(static_cast<int>(h % kFibonacciPoints))), g);
        };
      else
        corner_gradient_ = [](const SimplexNoise& s, std::uint64_t h, double* g) {
          scaled(well_behaved_rotating_gradient(fibonacci_angles(static_cast<int>(h % kFibonacciPoints)), s.cos_phase_,
                                                s.sin_phase_),
                 g);
        };
      return;
    }
  }
  if (phase == 0.0)
    corner_gradient_ = [](const SimplexNoise&, std::uint64_t h, double* g) { gradient_from_hash<N>(h, g); };
  else
    corner_gradient_ = [](const SimplexNoise& s, std::uint64_t h, double* g) {
      rotated_gradient_from_hash<N>(h, s.cos_phase_, s.sin_phase_, g);
    };
}

template <int N>
template <int M>
NoiseSample<N, M> SimplexNoise<N>::evaluate(const Vec<N>& x, int first_function) const {
  static_assert(M >= 1 && M <= N - 1);
  assert(first_function >= 0 && first_function + M <= kMaxFunctions);

  // Skew (F) and unskew (G) factors of the simplex lattice; see the header for the geometry.
  const double root = std::sqrt(static_cast<double>(N + 1));
  const double skew = (root - 1.0) / N;
  const double unskew = (1.0 - 1.0 / root) / N;

  const double skewed_shift = x.sum() * skew;
  std::array<std::int64_t, N> cell;
  Vec<N> frac;
  for (int j = 0; j < N; ++j) {
    const double y = x[j] + skewed_shift;
    const double fl = std::floor(y);
    cell[j] = static_cast<std::int64_t>(fl);
    frac[j] = y - fl;
  }
  // Offset from vertex 0 in unskewed space: unskew(y) - unskew(cell) = unskew(frac).
  Vec<N> offset = frac.array() - unskew * frac.sum();

  // rank[j] = position of axis j when the fractional parts are sorted in decreasing order
  // (ties broken by axis index); vertex k of the simplex has stepped along the axes of rank < k.
  std::array<int, N> axis_of_rank;
  for (int j = 0; j < N; ++j) {
    int rank = 0;
    for (int i = 0; i < N; ++i) rank += (frac[i] > frac[j]) || (frac[i] == frac[j] && i < j);
    axis_of_rank[rank] = j;
  }

  NoiseSample<N, M> out;
  for (int m = 0; m < M; ++m) {
    out.value[m] = 0.0;
    out.gradient[m].setZero();
  }

  std::array<std::int64_t, N> vertex = cell;
  for (int k = 0; k <= N; ++k) {
    if (k > 0) {
      // Step from vertex k-1 to vertex k: +1 along one axis in skewed space, which moves the
      // unskewed offset by -e_axis + G 1.
      const int axis = axis_of_rank[k - 1];
      vertex[axis] += 1;
      offset.array() += unskew;
      offset[axis] -= 1.0;
    }
    const double t = kKernelRadius2 - offset.squaredNorm();
    if (t <= 0.0) continue;
    const double t2 = t * t;
    const double t3 = t2 * t;
    const double t4 = t2 * t2;

    // Multiply-then-mix: sum_j vertex_j K_j with distinct odd 64-bit K_j, then one full mix64. The
    // N products are independent (a serial hash_combine chain cost ~100 cycles per vertex), and two
    // nearby lattice vertices collide only if sum_j d_j K_j = 0 mod 2^64 for small integers d_j.
    std::uint64_t key = seed_hash_;
    for (int j = 0; j < N; ++j) key += static_cast<std::uint64_t>(vertex[j]) * kAxisMultipliers[j];
    const std::uint64_t vertex_hash = mix64(key);

    for (int m = 0; m < M; ++m) {
      // An independent gradient per function: the vertex hash re-mixed with the function index.
      const std::uint64_t h = mix64(vertex_hash + static_cast<std::uint64_t>(first_function + m + 1) * kGoldenGamma);
      Vec<N> g;
      if (phase_ == 0.0 && rotation_ == GradientRotation::two_vector)  // the hot path, inlined: the phase-free noise
        gradient_from_hash<N>(h, g.data());
      else
        corner_gradient_(*this, h, g.data());
      const double g_dot_d = g.dot(offset);
      // d/dx [t^4 (g.d)] = t^4 g + 4 t^3 (g.d) dt/dx, with dt/dx = -2 d.
      out.value[m] += t4 * g_dot_d;
      out.gradient[m] += t4 * g - (8.0 * t3 * g_dot_d) * offset;
    }
  }
  return out;
}

// k_eff of simplex noise in closed form. Each vertex v contributes k(|d|^2) (g_v . d), d = x - v, with
// gradients independent between vertices, zero mean and E[g g^T] = (E|g|^2 / N) I (both gradient sets
// above are symmetric under axis permutations and sign flips). Cross terms vanish in expectation, and
// averaging over x sums the single-vertex terms over the whole lattice, so with
// rho = |d|, k' = dk/ds = -4 (r^2 - s)^3 and s = rho^2:
//   E n^2      ~ int rho^(N-1) k^2 rho^2 / N drho,
//   E |grad n|^2 ~ int rho^(N-1) [k^2 + (4 k k' rho^2 + 4 k'^2 rho^4) / N] drho
// (grad of k (g.d) is k g + 2 k' (g.d) d, and E (g.d)^2 = E|g|^2 rho^2 / N), with the same factor
// (vertex density, sphere area, E|g|^2) in front of both: it cancels in the ratio. The integrands are
// polynomials of degree < 40, so Simpson's rule on 2000 intervals is exact to rounding.
// tests/noise/test_noise_bases.cpp checks the result against a measurement.
double simplex_wavenumber(int dimension) {
  const double r2 = SimplexNoise<2>::kKernelRadius2;
  const int intervals = 2000;
  const double h = std::sqrt(r2) / intervals;
  double value = 0.0, gradient = 0.0;
  for (int k = 0; k <= intervals; ++k) {
    const double rho = k * h, s = rho * rho;
    const double weight = (k == 0 || k == intervals) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    const double t = r2 - s, kernel = t * t * t * t, slope = -4.0 * t * t * t;
    const double surface = std::pow(rho, dimension - 1);
    value += weight * surface * kernel * kernel * s / dimension;
    gradient += weight * surface * (kernel * kernel + (4.0 * kernel * slope * s + 4.0 * slope * slope * s * s) / dimension);
  }
  return std::sqrt(gradient / value);
}

template <int N>
SimplexNoiseFunctions<N>::SimplexNoiseFunctions(std::uint64_t seed, double phase, GradientRotation rotation)
    : noise_(seed, phase, rotation), wavenumber_(simplex_wavenumber(N)), amplitude_(simplex_field_amplitude(N)) {}

template <int N>
std::shared_ptr<const NoiseFunctions<N>> make_rotating_simplex_noise(std::uint64_t seed, double phase,
                                                                     GradientRotation rotation) {
  check_noise_phase(phase);
  return std::make_shared<const SimplexNoiseFunctions<N>>(seed, phase, rotation);
}

// Every dimension with the fused (all N-1 functions) and the single-function traversal; in 2D the
// two are the same instantiation.
#define DFVN_INSTANTIATE_NOISE(N)                                                             \
  template class SimplexNoise<N>;                                                             \
  template class SimplexNoiseFunctions<N>;                                                    \
  template std::shared_ptr<const NoiseFunctions<N>> make_rotating_simplex_noise<N>(std::uint64_t, double, GradientRotation); \
  template NoiseSample<N, N - 1> SimplexNoise<N>::evaluate<N - 1>(const Vec<N>&, int) const;

#define DFVN_INSTANTIATE_NOISE_SINGLE(N) \
  template NoiseSample<N, 1> SimplexNoise<N>::evaluate<1>(const Vec<N>&, int) const;

DFVN_INSTANTIATE_NOISE(2)
DFVN_INSTANTIATE_NOISE(3)
DFVN_INSTANTIATE_NOISE(4)
DFVN_INSTANTIATE_NOISE(5)
DFVN_INSTANTIATE_NOISE(6)
DFVN_INSTANTIATE_NOISE(7)
DFVN_INSTANTIATE_NOISE(8)
DFVN_INSTANTIATE_NOISE_SINGLE(3)
DFVN_INSTANTIATE_NOISE_SINGLE(4)
DFVN_INSTANTIATE_NOISE_SINGLE(5)
DFVN_INSTANTIATE_NOISE_SINGLE(6)
DFVN_INSTANTIATE_NOISE_SINGLE(7)
DFVN_INSTANTIATE_NOISE_SINGLE(8)
// 4D bitangent noise's optimised form: two of the three functions in one traversal.
template NoiseSample<4, 2> SimplexNoise<4>::evaluate<2>(const Vec<4>&, int) const;

#undef DFVN_INSTANTIATE_NOISE
#undef DFVN_INSTANTIATE_NOISE_SINGLE

}  // namespace dfvn
