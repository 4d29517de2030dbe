#include "dfvn/sampling/latin_hypercube.hpp"

#include <numeric>
#include <utility>
#include <vector>

#include "dfvn/core/hash.hpp"
#include "dfvn/core/parallel.hpp"

namespace dfvn {

PointSet latin_hypercube_points(int dimension, std::uint64_t count, const Box& domain, std::uint64_t seed, int threads) {
  PointSet out{dimension, Coordinates(count * static_cast<std::uint64_t>(dimension)), domain};
  const double stratum = 1.0 / static_cast<double>(count);
  // Axes are independent: one thread per axis, each permutation drawn sequentially.
#pragma omp parallel for schedule(static) num_threads(resolve_threads(threads)) if (worth_threads(out.coordinates.size()))
  for (int k = 0; k < dimension; ++k) {
    std::vector<std::uint64_t> order(count);
    std::iota(order.begin(), order.end(), std::uint64_t{0});
    const auto axis = static_cast<std::uint64_t>(k);
    for (std::uint64_t m = count; m > 1; --m) {
      const std::uint64_t pick = random_bits(seed, Stream::latin_hypercube, axis, m) % m;
      std::swap(order[m - 1], order[pick]);
    }
    for (std::uint64_t i = 0; i < count; ++i) {
      const double offset = random_unit(seed, Stream::latin_hypercube, i, axis + 1000);
      out.coordinates[i * static_cast<std::uint64_t>(dimension) + axis] =
          domain.lo + domain.side * ((static_cast<double>(order[i]) + offset) * stratum);
    }
  }
  return out;
}

}  // namespace dfvn
