#include "dfvn/noise/random_frame.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/QR>

namespace dfvn {

Eigen::MatrixXd random_frame(int n, std::uint64_t seed, Stream stream, std::uint64_t index, std::uint64_t first_lane) {
  Eigen::MatrixXd gaussian(n, n);
  for (int e = 0; e < n * n; ++e) {
    const auto lane = first_lane + 2 * static_cast<std::uint64_t>(e);
    const double u1 = 1.0 - random_unit(seed, stream, index, lane);  // in (0, 1]
    const double u2 = random_unit(seed, stream, index, lane + 1);
    gaussian(e / n, e % n) = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);  // Box-Muller
  }
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(gaussian);
  Eigen::MatrixXd q = qr.householderQ();
  for (int j = 0; j < n; ++j)
    if (qr.matrixQR()(j, j) < 0.0) q.col(j) = -q.col(j);
  return q;
}

}  // namespace dfvn
