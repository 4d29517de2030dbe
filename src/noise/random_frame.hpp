// Seeded Haar-random rotations, shared by the noise bases that decorrelate functions by orientation.
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include "dfvn/core/hash.hpp"

namespace dfvn {

// A Haar-random orthogonal n x n matrix for (seed, stream, index): QR of a Gaussian matrix whose
// entries use lanes first_lane .. first_lane + 2 n^2 - 1, with the signs of R's diagonal moved into Q
// (without that correction Q is not uniformly distributed). Dynamic size, compiled once in
// random_frame.cpp: a fixed-size HouseholderQR per dimension made gradient_noise.cpp and
// turning_bands.cpp the slowest files of the build (template instantiation was 73% of the former's
// compile time); the dynamic QR gives the same bits (compared for n = 2..9, 3000 draws each).
Eigen::MatrixXd random_frame(int n, std::uint64_t seed, Stream stream, std::uint64_t index, std::uint64_t first_lane);

template <int N>
Eigen::Matrix<double, N, N> random_frame(std::uint64_t seed, Stream stream, std::uint64_t index, std::uint64_t first_lane) {
  return random_frame(N, seed, stream, index, first_lane);
}

}  // namespace dfvn
