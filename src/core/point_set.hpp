// A point set in a cube-shaped domain (or the ball inscribed in it): the type every floor above core
// shares (generators make it, evaluators and the point files read it).
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include "dfvn/core/bulk_memory.hpp"
#include "dfvn/core/torus.hpp"

namespace dfvn {

// The cube [lo, lo + side]^N, or with `inscribed_ball` the ball inscribed in it (CNJ's --domain ball).
struct Box {
  double lo = 0.0;
  double side = 1.0;
  bool inscribed_ball = false;
  // Ball: pi^(N/2) / Gamma(N/2 + 1) (side / 2)^N.
  double volume(int dimension) const {
    const double cube = std::pow(side, dimension);
    if (!inscribed_ball) return cube;
    return cube * std::pow(0.25 * std::numbers::pi, 0.5 * dimension) / std::tgamma(0.5 * dimension + 1.0);
  }
  bool contains(const double* x, int dimension) const {
    for (int j = 0; j < dimension; ++j)
      if (!(x[j] >= lo && x[j] <= lo + side)) return false;
    if (!inscribed_ball) return true;
    double from_centre2 = 0.0;
    for (int j = 0; j < dimension; ++j) from_centre2 += (x[j] - lo - 0.5 * side) * (x[j] - lo - 0.5 * side);
    return from_centre2 <= 0.25 * side * side;
  }
};

// points: size() x dimension, row-major. Coordinates(n) leaves its numbers unwritten (core/bulk_memory.hpp):
// whoever sizes it writes every one.
struct PointSet {
  int dimension = 0;
  Coordinates coordinates;
  Box domain;
  std::size_t size() const { return dimension ? coordinates.size() / dimension : 0; }
  const double* point(std::size_t i) const { return coordinates.data() + i * dimension; }
};

// The (N-1)-dimensional area of the unit sphere S^{N-1}: 2 pi^(N/2) / Gamma(N/2).
inline double sphere_area(int dimension) {
  return 2.0 * std::pow(std::numbers::pi, 0.5 * dimension) / std::tgamma(0.5 * dimension);
}

}  // namespace dfvn
