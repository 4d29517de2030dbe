#include "sampling/jitter.hpp"

#include "core/hash.hpp"
#include "core/parallel.hpp"

namespace dfvn {

PointSet jittered_lattice(const LatticeSpec& lattice, std::uint64_t seed, int threads) {
  return jittered_lattice(lattice, jitter_half_width(lattice), seed, threads);
}

PointSet jittered_lattice(const LatticeSpec& lattice, double half_width, std::uint64_t seed, int threads) {
  const int n = lattice.dimension;
  const auto count = static_cast<std::int64_t>(lattice.point_count());
  const double h = half_width;
  PointSet out{n, std::vector<double>(static_cast<std::size_t>(count) * n), Box{0.0, 1.0}};
#pragma omp parallel for schedule(static) num_threads(resolve_threads(threads))
  for (std::int64_t i = 0; i < count; ++i) {
    double* x = out.coordinates.data() + i * n;
    lattice.point(static_cast<std::uint64_t>(i), x);
    for (int j = 0; j < n; ++j)
      x[j] += h * (2.0 * random_unit(seed, Stream::jitter, static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(j)) - 1.0);
  }
  return out;
}

PointSet uniform_random_points(int dimension, std::uint64_t count, const Box& domain, std::uint64_t seed, int threads) {
  PointSet out{dimension, std::vector<double>(count * static_cast<std::uint64_t>(dimension)), domain};
#pragma omp parallel for schedule(static) num_threads(resolve_threads(threads))
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(count); ++i)
    for (int j = 0; j < dimension; ++j)
      out.coordinates[static_cast<std::size_t>(i) * dimension + j] =
          domain.lo + domain.side * random_unit(seed, Stream::random_points, static_cast<std::uint64_t>(i),
                                                static_cast<std::uint64_t>(j));
  return out;
}

}  // namespace dfvn
