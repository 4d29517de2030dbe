#include "dfvn/sampling/lattice.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "dfvn/core/message_text.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dfvn {

Method parse_method(std::string_view name) {
  if (name == "cnj") return Method::cnj;
  if (name == "jitter") return Method::jitter;
  if (name == "jitter-matched") return Method::jitter_matched;
  if (name == "pds") return Method::pds;
  if (name == "sobol") return Method::sobol;
  if (name == "random") return Method::random;
  if (name == "halton") return Method::halton;
  if (name == "lhs") return Method::lhs;
  throw std::invalid_argument("unknown method " + quote_for_message(name) + " (allowed: " + method_names() + ")");
}

std::string_view to_string(Method method) {
  switch (method) {
    case Method::cnj: return "cnj";
    case Method::jitter: return "jitter";
    case Method::jitter_matched: return "jitter-matched";
    case Method::pds: return "pds";
    case Method::sobol: return "sobol";
    case Method::random: return "random";
    case Method::halton: return "halton";
    case Method::lhs: return "lhs";
  }
  return "?";
}

std::string method_names() {
  std::string names;
  for (Method m : kAllMethods) names += (names.empty() ? "" : ", ") + std::string(to_string(m));
  return names;
}

Protocol parse_protocol(std::string_view name) {
  if (name == "paper") return Protocol::paper;
  if (name == "fair") return Protocol::fair;
  throw std::invalid_argument("unknown protocol " + quote_for_message(name) + " (allowed: fair, paper)");
}

std::string_view to_string(Protocol protocol) { return protocol == Protocol::paper ? "paper" : "fair"; }

std::uint64_t LatticeSpec::point_count() const {
  if (grid < 2) throw std::invalid_argument("grid must be at least 2, got " + std::to_string(grid));
  std::uint64_t count = 1;
  for (int j = 0; j < dimension; ++j) {
    if (count > (std::uint64_t{1} << 62) / static_cast<std::uint64_t>(grid))
      throw std::invalid_argument("grid^dim = " + std::to_string(grid) + "^" + std::to_string(dimension) +
                                  " is too large");
    count *= static_cast<std::uint64_t>(grid);
  }
  return count;
}

double LatticeSpec::spacing() const {
  return protocol == Protocol::paper ? (1.0 - kPaperDelta) / (grid - 1) : 1.0 / grid;
}

double LatticeSpec::coordinate(int i) const {
  return protocol == Protocol::paper ? 0.5 * kPaperDelta + i * spacing() : (i + 0.5) / grid;
}

Box LatticeSpec::cells() const {
  if (protocol == Protocol::fair) return Box{0.0, 1.0};
  const double h = spacing();
  return Box{coordinate(0) - 0.5 * h, static_cast<double>(grid) * h};
}

void LatticeSpec::point(std::uint64_t index, double* out) const {
  const auto k = static_cast<std::uint64_t>(grid);
  for (int j = 0; j < dimension; ++j) {
    out[j] = coordinate(static_cast<int>(index % k));
    index /= k;
  }
}

double jitter_half_width(const LatticeSpec& lattice) {
  return lattice.protocol == Protocol::paper ? 0.5 * kPaperDelta : 0.5 / lattice.grid;
}

int grid_for_count(int dimension, std::uint64_t count) {
  if (dimension < 1) throw std::invalid_argument("dimension must be at least 1, got " + std::to_string(dimension));
  if (count == 0) throw std::invalid_argument("the point count must be at least 1");
  // K^N in double is exact up to 2^53 and monotone beyond, which is all the comparison needs.
  const auto lattice_size = [&](int k) { return std::pow(static_cast<double>(k), dimension); };
  const auto target = static_cast<double>(count);
  const double root = std::floor(std::pow(target, 1.0 / dimension));
  if (root >= 0x1p30)
    throw std::invalid_argument(fmt::format("{} points in {}D need a lattice of more than 2^30 points per axis", count, dimension));
  int k = std::max(2, static_cast<int>(root));
  while (k > 2 && lattice_size(k) > target) --k;        // pow's rounding: step to K^N <= count
  while (lattice_size(k + 1) <= target) ++k;
  return (lattice_size(k + 1) - target < target - lattice_size(k)) ? k + 1 : k;
}

double average_neighbour_distance(int dimension) {
  double sum = 0.0, binomial = 1.0;
  for (int i = 1; i <= dimension; ++i) {
    binomial = binomial * (dimension - i + 1) / i;
    sum += std::pow(2.0, i) * binomial * std::sqrt(static_cast<double>(i));
  }
  return sum / (std::pow(3.0, dimension) - 1.0);
}

std::vector<double> lattice_displacements(const LatticeSpec& lattice, const PointSet& points) {
  if (points.dimension != lattice.dimension || points.size() != lattice.point_count())
    throw std::invalid_argument("lattice displacements: the point set is not one point per lattice site");
  std::vector<double> u(points.coordinates.size());
  std::vector<double> site(static_cast<std::size_t>(lattice.dimension));
  for (std::size_t i = 0; i < points.size(); ++i) {
    lattice.point(i, site.data());
    for (int a = 0; a < lattice.dimension; ++a) u[i * lattice.dimension + a] = points.point(i)[a] - site[a];
  }
  return u;
}

}  // namespace dfvn
