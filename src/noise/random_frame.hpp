// Seeded Haar-random rotations, shared by the noise bases that decorrelate functions by orientation.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>

#include <Eigen/Core>
#include <Eigen/QR>

#include "dfvn/core/hash.hpp"

namespace dfvn {

// A Haar-random orthogonal N x N matrix for (seed, stream, index): QR of a Gaussian matrix whose
// entries use lanes first_lane .. first_lane + 2 N^2 - 1, with the signs of R's diagonal moved into Q
// (without that correction Q is not uniformly distributed).
template <int N>
Eigen::Matrix<double, N, N> random_frame(std::uint64_t seed, Stream stream, std::uint64_t index, std::uint64_t first_lane) {
  Eigen::Matrix<double, N, N> gaussian;
  for (int e = 0; e < N * N; ++e) {
    const auto lane = first_lane + 2 * static_cast<std::uint64_t>(e);
    const double u1 = 1.0 - random_unit(seed, stream, index, lane);  // in (0, 1]
    const double u2 = random_unit(seed, stream, index, lane + 1);
    gaussian(e / N, e % N) = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);  // Box-Muller
  }
  const Eigen::HouseholderQR<Eigen::Matrix<double, N, N>> qr(gaussian);
  Eigen::Matrix<double, N, N> q = qr.householderQ();
  for (int j = 0; j < N; ++j)
    if (qr.matrixQR()(j, j) < 0.0) q.col(j) = -q.col(j);
  return q;
}

}  // namespace dfvn
