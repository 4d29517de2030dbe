// The domain on which the noise is defined: every coordinate of the noise argument u = F x (frequency
// times point) below kMaxNoiseArgument in magnitude, and frequencies in [kMinNoiseFrequency,
// kMaxNoiseFrequency]. Entry points (DfvnField's constructor, the field command's point table, the
// CNJ and image-warp configurations) check it before any parallel loop starts; tracers stop at its
// edge instead of evaluating outside it (integrate/trace_impl.hpp).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

#include <fmt/format.h>

namespace dfvn {

// Why 2^50. Simplex noise skews u to y_j = u_j + s (u_1 + ... + u_N) with s = (sqrt(N+1) - 1) / N,
// so |y_j| <= (1 + N s) max|u| = sqrt(N+1) max|u| <= 3 max|u| for N <= 8. With max|u| < 2^50 every
// |y_j| < 3 * 2^50 < 2^52, where
//   - floor(y_j) is an exact integer, and it and its neighbour cell floor(y_j) + 1 convert to int64
//     without overflow (beyond 2^63 the conversion is undefined behaviour: the crash of issue 9);
//   - the cell offset y_j - floor(y_j) is computed exactly (both are multiples of ulp(y_j) <= 1/2)
//     and lies in [0, 1), so every vertex offset, kernel and gradient is finite;
//   - the sum of the N coordinates cannot overflow.
// The field evaluates each basis at s x with s = 2 pi F / k_eff (field/dfvn_field.hpp): simplex has
// 2 pi / k_eff < 1 in every dimension, so the argument above bounds its s x as well; turning bands
// (2 pi / k_eff = 1.73) reads band coordinates w . (s x) + o with |w| = 1, at most
// sqrt(8) * 1.73 * 2^50 + 1 < 2^53 in magnitude: floor is exact there, its int64 conversion defined,
// and the in-cell offset in [0, 1).
// Resolution degrades with |u|: near the bound a double resolves a quarter of a noise cell, so the
// noise there is coarse, but it is defined and finite.
inline constexpr double kMaxNoiseArgument = 0x1p50;

// Frequencies. At most 2^50, so that the cube [-1, 1]^N, where every sampler of this library lives,
// is always inside the domain. At least 2^-50: the noise values are f_i = (A_N / F) n_i(F x), and a
// smaller F (a subnormal one overflows A_N / F to Inf) makes them grow without bound.
inline constexpr double kMaxNoiseFrequency = kMaxNoiseArgument;
inline constexpr double kMinNoiseFrequency = 1.0 / kMaxNoiseArgument;

// True when |u| < kMaxNoiseArgument (false for NaN and Inf).
inline bool is_noise_argument(double u) { return std::abs(u) < kMaxNoiseArgument; }

// True when every coordinate of u (an Eigen vector or any range of doubles) is a noise argument.
template <typename Vector>
bool in_noise_domain(const Vector& u) {
  for (int j = 0; j < static_cast<int>(u.size()); ++j)
    if (!is_noise_argument(u[j])) return false;
  return true;
}

// Throws std::invalid_argument unless frequency * coordinate is a noise argument. `what` names the
// value for the message, e.g. "line 3, column 2" or "--frequency".
inline void check_noise_argument(double coordinate, double frequency, std::string_view what) {
  if (!is_noise_argument(frequency * coordinate))
    throw std::invalid_argument(fmt::format(
        "{}: {} is outside the noise domain: |frequency x coordinate| = |{} x {}| must be below "
        "2^50 = {:g}",
        what, coordinate, frequency, coordinate, kMaxNoiseArgument));
}

// Throws std::invalid_argument unless frequency is in [kMinNoiseFrequency, kMaxNoiseFrequency].
inline void check_noise_frequency(double frequency, std::string_view what = "frequency") {
  if (!(frequency >= kMinNoiseFrequency && frequency <= kMaxNoiseFrequency))
    throw std::invalid_argument(fmt::format("{} must be in [2^-50, 2^50] = [{:g}, {:g}], got {:g}", what,
                                            kMinNoiseFrequency, kMaxNoiseFrequency, frequency));
}

}  // namespace dfvn
