// A direction given by the user (--stretch's U, --steer-dir, Python's stretch and steer): any finite
// length, 1e-300 and 1e300 components included. Its square sum would underflow to 0 or overflow to Inf,
// so it is first scaled by a power of two (exact) to a largest |component| in [1, 2), and then divided by
// its norm, whose square sum is then in [1, 4N]: no direction of finite, non-zero length is lost.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

namespace dfvn {

// Whether U (finite components) has a component that is not zero: then unit_direction gives it.
inline bool is_direction(const std::vector<double>& u) {
  return std::all_of(u.begin(), u.end(), [](double c) { return std::isfinite(c); }) &&
         std::any_of(u.begin(), u.end(), [](double c) { return c != 0.0; });
}

// U / |U| for a U that is_direction.
template <int N>
Eigen::Matrix<double, N, 1> unit_direction(const Eigen::Matrix<double, N, 1>& u) {
  const int exponent = std::ilogb(u.cwiseAbs().maxCoeff());
  Eigen::Matrix<double, N, 1> scaled;  // component by component: 2^-exponent itself overflows for subnormal U
  for (int j = 0; j < N; ++j) scaled[j] = std::ldexp(u[j], -exponent);
  return scaled / scaled.norm();
}

}  // namespace dfvn
