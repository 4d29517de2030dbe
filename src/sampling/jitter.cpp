#include "dfvn/sampling/jitter.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/hash.hpp"
#include "dfvn/core/torus.hpp"
#include "dfvn/core/parallel.hpp"

namespace dfvn {

PointSet jittered_lattice(const LatticeSpec& lattice, std::uint64_t seed, int threads) {
  return jittered_lattice(lattice, jitter_half_width(lattice), seed, threads);
}

PointSet jittered_lattice(const LatticeSpec& lattice, double half_width, std::uint64_t seed, int threads) {
  return jittered_lattice_range(lattice, half_width, 0, lattice.point_count(), seed, threads);
}

PointSet jittered_lattice_range(const LatticeSpec& lattice, double half_width, std::uint64_t first, std::uint64_t count,
                                std::uint64_t seed, int threads) {
  const int n = lattice.dimension;
  const auto rows = static_cast<std::int64_t>(count);
  const double h = half_width;
  PointSet out{n, Coordinates(static_cast<std::size_t>(count) * n), Box{0.0, 1.0}};
#pragma omp parallel for schedule(static) num_threads(resolve_threads(threads)) if (worth_threads(out.coordinates.size()))
  for (std::int64_t r = 0; r < rows; ++r) {
    const std::uint64_t i = first + static_cast<std::uint64_t>(r);
    double* x = out.coordinates.data() + r * n;
    lattice.point(i, x);
    for (int j = 0; j < n; ++j)
      x[j] += h * (2.0 * random_unit(seed, Stream::jitter, i, static_cast<std::uint64_t>(j)) - 1.0);
  }
  return out;
}

PointSet jittered_sites_in_ball(const LatticeSpec& lattice, std::uint64_t seed, int threads) {
  const int n = lattice.dimension;
  const Domain ball = Domain::unit(DomainKind::ball);
  const double h = jitter_half_width(lattice);
  const auto inside_strictly = [n](const double* x) {
    double from_centre2 = 0.0;
    for (int j = 0; j < n; ++j) from_centre2 += (x[j] - 0.5) * (x[j] - 0.5);
    return from_centre2 < 0.25;
  };
  std::vector<double> sites;
  std::vector<double> x(n);
  const std::uint64_t count = lattice.point_count();
  for (std::uint64_t i = 0; i < count; ++i) {
    lattice.point(i, x.data());
    if (inside_strictly(x.data())) sites.insert(sites.end(), x.begin(), x.end());
  }
  const auto rows = static_cast<std::int64_t>(sites.size() / n);
  PointSet out{n, Coordinates(sites.size()), ball};
  constexpr std::uint64_t kAttempts = 4096;
#pragma omp parallel for schedule(static) num_threads(resolve_threads(threads)) if (worth_threads(out.coordinates.size()))
  for (std::int64_t r = 0; r < rows; ++r) {
    const double* site = sites.data() + r * n;
    double* y = out.coordinates.data() + r * n;
    std::copy(site, site + n, y);
    for (std::uint64_t attempt = 0; attempt < kAttempts; ++attempt) {
      const std::uint64_t key = hash_combine(static_cast<std::uint64_t>(r), attempt);
      for (int j = 0; j < n; ++j)
        y[j] = site[j] + h * (2.0 * random_unit(seed, Stream::jitter, key, static_cast<std::uint64_t>(j)) - 1.0);
      if (ball.contains(y, n)) break;
      if (attempt + 1 == kAttempts) std::copy(site, site + n, y);
    }
  }
  return out;
}

namespace {

// The offsets v_i of jittered_lattice, uniform in [-1, 1]^N: K^N x N, row-major.
std::vector<double> unit_offsets(const LatticeSpec& lattice, std::uint64_t seed, int threads) {
  const int n = lattice.dimension;
  const auto count = static_cast<std::int64_t>(lattice.point_count());
  std::vector<double> v(static_cast<std::size_t>(count) * n);
#pragma omp parallel for schedule(static) num_threads(resolve_threads(threads)) if (worth_threads(v.size()))
  for (std::int64_t i = 0; i < count; ++i)
    for (int j = 0; j < n; ++j)
      v[static_cast<std::size_t>(i) * n + j] =
          2.0 * random_unit(seed, Stream::jitter, static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(j)) - 1.0;
  return v;
}

// x folded into [0, 1] by reflection at 0 and 1 (period 2).
double reflect_into_unit(double x) {
  const double y = x - 2.0 * std::floor(0.5 * x);  // [0, 2)
  return y <= 1.0 ? y : 2.0 - y;
}

// sqrt(mean_i |d_i|^2), the sums in index order.
double rms_of(const std::vector<double>& d, std::size_t rows) {
  double sum = 0.0;
  for (double x : d) sum += x * x;
  return std::sqrt(sum / static_cast<double>(rows));
}

}  // namespace

MatchedJitter jitter_matching_rms(const LatticeSpec& lattice, double rms, JitterBoundary boundary, std::uint64_t seed,
                                  int threads) {
  if (!(rms > 0.0 && std::isfinite(rms)))
    throw std::invalid_argument(fmt::format("the RMS displacement to match must be finite and positive, got {:g}", rms));
  const int n = lattice.dimension;
  const std::size_t rows = lattice.point_count();
  const std::vector<double> v = unit_offsets(lattice, seed, threads);
  std::vector<double> sites(v.size());
  for (std::size_t i = 0; i < rows; ++i) lattice.point(i, sites.data() + i * n);

  MatchedJitter out;
  out.displacements.resize(v.size());
  // The displacements for half-width a: a v_i, or the reflected point minus its site.
  const auto displace = [&](double a) {
    for (std::size_t k = 0; k < v.size(); ++k)
      out.displacements[k] =
          boundary == JitterBoundary::wrap ? a * v[k] : reflect_into_unit(sites[k] + a * v[k]) - sites[k];
    return rms_of(out.displacements, rows);
  };
  double a = rms / rms_of(v, rows);  // exact for wrap; reflection only shortens, so a lower bound there
  if (boundary == JitterBoundary::reflect) {
    double lo = a, hi = a;
    for (int k = 0; displace(hi) < rms; ++k) {
      if (k == 60)
        throw std::invalid_argument(fmt::format("reflected jitter cannot move points an RMS {:g} in the unit cube", rms));
      lo = hi;
      hi *= 2.0;
    }
    // displace(lo) < rms <= displace(hi): bisection to the last bit of a.
    for (int k = 0; k < 200 && lo < hi; ++k) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      (displace(mid) < rms ? lo : hi) = mid;
    }
    a = std::abs(displace(lo) - rms) <= std::abs(displace(hi) - rms) ? lo : hi;
  }
  // The bisection assumes the RMS grows with a, as it does while the interior, where nothing is
  // reflected, dominates; check that it found the value.
  if (!(std::abs(displace(a) - rms) <= 1e-12 * rms))
    throw std::invalid_argument(fmt::format("reflected jitter cannot match an RMS displacement of {:g} on this lattice", rms));
  out.half_width = a;
  out.points = PointSet{n, Coordinates(v.size()), Box{0.0, 1.0}};
  for (std::size_t k = 0; k < v.size(); ++k) {
    const double x = sites[k] + a * v[k];
    out.points.coordinates[k] = boundary == JitterBoundary::wrap ? x : reflect_into_unit(x);
  }
  if (boundary == JitterBoundary::wrap) wrap_to_unit_torus(out.points.coordinates.data(), out.points.coordinates.size());
  return out;
}

PointSet uniform_random_points(int dimension, std::uint64_t count, const Box& domain, std::uint64_t seed, int threads) {
  return uniform_random_points_range(dimension, 0, count, domain, seed, threads);
}

PointSet uniform_random_points_range(int dimension, std::uint64_t first, std::uint64_t count, const Box& domain,
                                     std::uint64_t seed, int threads) {
  PointSet out{dimension, Coordinates(count * static_cast<std::uint64_t>(dimension)), domain};
#pragma omp parallel for schedule(static) num_threads(resolve_threads(threads)) if (worth_threads(out.coordinates.size()))
  for (std::int64_t r = 0; r < static_cast<std::int64_t>(count); ++r)
    for (int j = 0; j < dimension; ++j)
      out.coordinates[static_cast<std::size_t>(r) * dimension + j] =
          domain.lo + domain.side * random_unit(seed, Stream::random_points, first + static_cast<std::uint64_t>(r),
                                                static_cast<std::uint64_t>(j));
  return out;
}

}  // namespace dfvn
