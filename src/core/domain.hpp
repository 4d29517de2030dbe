// Where a point set lives: one domain object that every generator and evaluator consults (its
// volume, its metric, how a point is wrapped or tested, how it is described), chosen once per run.
#pragma once

#include <cmath>
#include <numbers>
#include <string>
#include <string_view>

namespace dfvn {

// The cube [lo, lo + side]^N: the region a generator fills and the bounding box of every domain.
struct Box {
  double lo = 0.0;
  double side = 1.0;
  double volume(int dimension) const { return std::pow(side, dimension); }
  bool contains(const double* x, int dimension) const {
    for (int j = 0; j < dimension; ++j)
      if (!(x[j] >= lo && x[j] <= lo + side)) return false;
    return true;
  }
};

// torus: [lo, lo + side)^N with opposite faces identified (no boundary; minimum-image distances).
// cube: [lo, lo + side]^N (Euclidean distances). ball: the ball inscribed in that cube (centre
// lo + side/2, radius side/2). sphere: the sphere S^{N-1} inscribed in it (the unit sphere for
// lo = -1, side = 2; geodesic distances).
enum class DomainKind { torus, cube, ball, sphere };
inline constexpr DomainKind kAllDomainKinds[] = {DomainKind::torus, DomainKind::cube, DomainKind::ball,
                                                 DomainKind::sphere};
// The main job's: the torus has no boundary, so every method meets the same neighbourhood everywhere
// (data/boundary_shares.md).
inline constexpr DomainKind kDefaultDomainKind = DomainKind::torus;
DomainKind parse_domain_kind(std::string_view name);  // throws std::invalid_argument listing the names
std::string_view to_string(DomainKind kind);
std::string domain_kind_names();  // "torus, cube, ball, sphere"

// Volume of the unit ball in N dimensions, pi^(N/2) / Gamma(N/2 + 1).
inline double unit_ball_volume(int dimension) {
  return std::pow(std::numbers::pi, 0.5 * dimension) / std::tgamma(0.5 * dimension + 1.0);
}

// The (N-1)-dimensional area of the unit sphere S^{N-1}: 2 pi^(N/2) / Gamma(N/2).
inline double sphere_area(int dimension) {
  return 2.0 * std::pow(std::numbers::pi, 0.5 * dimension) / std::tgamma(0.5 * dimension);
}

struct Domain {
  DomainKind kind = DomainKind::cube;
  double lo = 0.0;
  double side = 1.0;

  constexpr Domain() = default;
  constexpr Domain(DomainKind k, double l, double s) : kind(k), lo(l), side(s) {}
  // A box is the cube it spans (point files without a description are measured there).
  constexpr Domain(const Box& box) : kind(DomainKind::cube), lo(box.lo), side(box.side) {}  // NOLINT: implicit
  // The unit domain of a kind: [0,1)^N, [0,1]^N, the ball inscribed in it, the unit sphere S^{N-1}.
  static Domain unit(DomainKind kind) {
    return kind == DomainKind::sphere ? Domain{kind, -1.0, 2.0} : Domain{kind, 0.0, 1.0};
  }

  Box box() const { return {lo, side}; }
  bool periodic() const { return kind == DomainKind::torus; }
  // The dimension of the manifold the points fill: N, or N - 1 on the sphere.
  int manifold_dimension(int dimension) const { return kind == DomainKind::sphere ? dimension - 1 : dimension; }
  // Its volume (the sphere: its area), the measure density is counted against.
  double measure(int dimension) const {
    const double radius = 0.5 * side;
    switch (kind) {
      case DomainKind::torus:
      case DomainKind::cube: return std::pow(side, dimension);
      case DomainKind::ball: return unit_ball_volume(dimension) * std::pow(radius, dimension);
      case DomainKind::sphere: return sphere_area(dimension) * std::pow(radius, dimension - 1);
    }
    return 0.0;
  }
  // Whether x lies in the domain: the closed box for the torus and the cube (a file may hold a
  // coordinate on the torus' upper face, the same point as its lower one), the closed ball, and for the
  // sphere a point within 1e-9 of its radius.
  bool contains(const double* x, int dimension) const {
    if (!box().contains(x, dimension) && kind != DomainKind::sphere) return false;
    if (kind == DomainKind::torus || kind == DomainKind::cube) return true;
    const double centre = lo + 0.5 * side, radius = 0.5 * side;
    double from_centre2 = 0.0;
    for (int j = 0; j < dimension; ++j) from_centre2 += (x[j] - centre) * (x[j] - centre);
    if (kind == DomainKind::ball) return from_centre2 <= radius * radius;
    return std::abs(std::sqrt(from_centre2) - radius) <= 1e-9 * radius;
  }
  // The torus: every coordinate into [lo, lo + side) (and lo where rounding gives lo + side). Other
  // kinds: unchanged.
  void wrap(double* x, int dimension) const {
    if (kind != DomainKind::torus) return;
    for (int j = 0; j < dimension; ++j) {
      const double u = (x[j] - lo) / side;
      const double wrapped = u - std::floor(u);
      x[j] = wrapped < 1.0 ? lo + side * wrapped : lo;
    }
  }
  // Squared distance in the domain's metric, for points inside it: minimum image on the torus, the
  // straight line otherwise (on the sphere the chord, which orders pairs as the geodesic does).
  double distance2(const double* a, const double* b, int dimension) const {
    double sum = 0.0;
    for (int j = 0; j < dimension; ++j) {
      double d = std::abs(a[j] - b[j]);
      if (kind == DomainKind::torus && d > 0.5 * side) d = side - d;
      sum += d * d;
    }
    return sum;
  }
  // "the torus [0, 1)^7", "the cube [0, 0.6]^7", "the ball of radius 0.5 centred at 0.5", "the sphere S^6".
  std::string describe(int dimension) const;
};

inline bool operator==(const Domain& a, const Domain& b) {
  return a.kind == b.kind && a.lo == b.lo && a.side == b.side;
}

}  // namespace dfvn
