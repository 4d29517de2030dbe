// A point set in a cube-shaped domain, and the names of the generators and protocols.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "core/torus.hpp"

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

// points: size() x dimension, row-major.
struct PointSet {
  int dimension = 0;
  std::vector<double> coordinates;
  Box domain;
  std::size_t size() const { return dimension ? coordinates.size() / dimension : 0; }
  const double* point(std::size_t i) const { return coordinates.data() + i * dimension; }
};

// jitter_matched: jitter whose RMS displacement equals CNJ's in the same run (sampling/jitter.hpp).
enum class Method { cnj, jitter, jitter_matched, pds, sobol, random, halton, lhs };
inline constexpr Method kAllMethods[] = {Method::cnj,   Method::jitter, Method::jitter_matched, Method::pds,
                                         Method::sobol, Method::random, Method::halton,         Method::lhs};
Method parse_method(std::string_view name);  // throws std::invalid_argument listing the names
std::string_view to_string(Method method);
std::string method_names();  // "cnj, jitter, jitter-matched, ..."

// paper: Section 5.1 exactly as data/PROTOCOL.md establishes it. unit: every method in the unit
// cube at the density of a cell-centred K^N lattice.
enum class Protocol { paper, unit };
Protocol parse_protocol(std::string_view name);
std::string_view to_string(Protocol protocol);

}  // namespace dfvn
