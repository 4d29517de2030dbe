// Exact uniform points in the spherical annulus r <= |d| <= 2r in N dimensions, from standard normal
// numbers made by the ziggurat method: the candidates of Poisson disk sampling, with no logarithm,
// cosine or power per point.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>

#include "dfvn/core/hash.hpp"

namespace dfvn {

// SplitMix64 (Steele, Lea and Flood 2014) from a hashed state: a stream of random words keyed by
// whatever the state was hashed from.
struct RandomWords {
  std::uint64_t state;
  std::uint64_t operator()() {
    state += kGoldenGamma;
    return mix64(state);
  }
};

// bits_to_unit(w), the top 53 bits over 2^53, converted as a signed integer: one instruction on
// x86-64, where an unsigned 64-bit conversion takes a branch and two.
inline double unit_from_top_bits(std::uint64_t w) {
  return static_cast<double>(static_cast<std::int64_t>(w >> 11)) * 0x1.0p-53;
}

// Standard normal numbers by the ziggurat (Marsaglia and Tsang 2000, "The ziggurat method for
// generating random variables"): the area under f(x) = exp(-x^2/2), x >= 0, is covered by 256 strips
// of equal area v; strip 0 is the base [0, r] x [0, f(r)] with the tail x > r, strip i >= 1 spans
// heights [f(x_i), f(x_{i+1})] over [0, x_i]. A uniform point of a uniform strip lies under the curve
// without further test in ~99% of draws; only the strips' right ends need exp() and the tail log().
// Exact: every accepted x has the half-normal density, and a random sign makes it normal.
class NormalZiggurat {
 public:
  static constexpr int kStrips = 256;

  static const NormalZiggurat& instance() {
    static const NormalZiggurat ziggurat;
    return ziggurat;
  }

  // A draw's first try, from one word (bits 0-7 pick the strip, bit 8 the sign, bits 11-63 the
  // abscissa): true, with x, when the point falls in the part of its strip wholly under the curve.
  bool core(std::uint64_t w, double& x) const {
    const std::size_t strip = w & 0xFF;
    const double magnitude = unit_from_top_bits(w) * x_[strip];
    x = (w & 0x100) != 0 ? -magnitude : magnitude;
    return magnitude < x_[strip + 1];
  }

  // The rest of a draw whose first try, word w, fell outside the core: the strip's wedge under the
  // curve, or the tail, else new tries with the next words.
  template <class Words>
  double beyond_core(std::uint64_t w, Words& words) const {
    for (;;) {
      const std::size_t strip = w & 0xFF;
      const double sign = (w & 0x100) != 0 ? -1.0 : 1.0;
      const double x = unit_from_top_bits(w) * x_[strip];
      if (strip == 0) {  // the tail x > r (Marsaglia 1964)
        double a, b;
        do {
          a = -std::log(1.0 - unit_from_top_bits(words())) / tail_;
          b = -std::log(1.0 - unit_from_top_bits(words()));
        } while (2.0 * b < a * a);
        return sign * (tail_ + a);
      }
      if (f_[strip] + unit_from_top_bits(words()) * (f_[strip + 1] - f_[strip]) < std::exp(-0.5 * x * x)) return sign * x;
      w = words();
      double y;
      if (core(w, y)) return y;
    }
  }

  template <class Words>
  double operator()(Words& words) const {
    const std::uint64_t w = words();
    double x;
    return core(w, x) ? x : beyond_core(w, words);
  }

  // r, where the tail begins: 3.6541528853610088 for 256 strips (Marsaglia and Tsang's table).
  double tail_start() const { return tail_; }

 private:
  static double f(double x) { return std::exp(-0.5 * x * x); }
  static double f_inverse(double y) { return std::sqrt(-2.0 * std::log(y)); }
  // Every strip's area when the base strip ends at r: r f(r) plus the tail's integral.
  static double strip_area(double r) {
    return r * f(r) + std::sqrt(0.5 * std::numbers::pi) * std::erfc(r / std::numbers::sqrt2);
  }

  // Stacks strips of area v(r) upwards from x_1 = r; returns the top strip's area minus v: > 0 when
  // r is too large (the strips are too thin to reach the top), < 0 when they overshoot it.
  double stack(double r) {
    const double v = strip_area(r);
    x_[0] = v / f(r);
    x_[1] = r;
    for (int i = 1; i + 1 < kStrips; ++i) {
      const double height = v / x_[i] + f(x_[i]);
      if (height >= 1.0) return -1.0;
      x_[i + 1] = f_inverse(height);
    }
    x_[kStrips] = 0.0;
    return x_[kStrips - 1] * (1.0 - f(x_[kStrips - 1])) - v;
  }

  // r solves stack(r) = 0, by bisection to the last bit.
  NormalZiggurat() {
    double low = 2.0, high = 5.0;
    for (;;) {
      const double mid = 0.5 * (low + high);
      if (mid <= low || mid >= high) break;
      (stack(mid) > 0.0 ? high : low) = mid;
    }
    tail_ = high;
    stack(tail_);
    for (int i = 0; i <= kStrips; ++i) f_[i] = f(x_[i]);
  }

  double x_[kStrips + 1];  // x_[0] = v / f(r) (the base strip's width with its tail), x_[1] = r > ... > x_[256] = 0
  double f_[kStrips + 1];  // f(x_i); f_[256] = 1
  double tail_ = 0.0;
};

// An offset d uniform in the volume of the annulus r <= |d| <= 2r, exactly: N + 2 normal numbers give
// a point uniform on the sphere S^(N+1), whose first N coordinates are uniform in the N-ball (Voelker,
// Gosmann and Stewart 2017, "Efficiently sampling vectors and coordinates from the n-sphere and
// n-ball"); scaled by 2r, and drawn again when inside radius r (a fraction 2^-N), they are uniform in
// the annulus. offset: N values.
template <int N>
void uniform_in_annulus(RandomWords& words, const NormalZiggurat& normal, double r, double* offset) {
  for (;;) {
    // N + 2 words first, so that their mixing and the cores' tests overlap; the few draws that leave
    // the core continue with the words after them.
    std::uint64_t w[N + 2];
    for (int j = 0; j < N + 2; ++j) w[j] = words();
    double g[N + 2];
    bool all_core = true;
    for (int j = 0; j < N + 2; ++j) all_core &= normal.core(w[j], g[j]);
    if (!all_core)
      for (int j = 0; j < N + 2; ++j)
        if (!normal.core(w[j], g[j])) g[j] = normal.beyond_core(w[j], words);
    double inner2 = 0.0;
    for (int j = 0; j < N; ++j) inner2 += g[j] * g[j];
    const double all2 = inner2 + g[N] * g[N] + g[N + 1] * g[N + 1];
    if (!(all2 > 0.0) || 4.0 * inner2 < all2) continue;  // |d|^2 = 4 r^2 inner2 / all2 < r^2
    const double scale = 2.0 * r / std::sqrt(all2);
    for (int j = 0; j < N; ++j) offset[j] = scale * g[j];
    return;
  }
}

}  // namespace dfvn
