// The leaf-size study behind stats/nearest_other.hpp's kLeafSize: for one point set (an N-column .npy, as
// `dfvn-sample --points DIR --format npy` writes), the time of the Euclidean nearest-neighbour search on one
// thread (nanoflann's tree build, the search's index and every point's query: what the `stats` subcommand's
// seconds_stats spends before its summary) for leaves of up to 16-128 points, for each build of the search
// this CPU runs (baseline, AVX2, AVX-512). Median of --repeats runs. Every run must find the same nearest
// distances (checked); the study decides speed only. --periodic: the search on the torus [0,1)^N instead
// (minimum-image distances, as the main job's statistics).
//   build/bench/nearest_leaf_sizes [--periodic] SET.npy [REPEATS]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "dfvn/core/dimension.hpp"
#include "dfvn/io/point_reader.hpp"
#include "dfvn/stats/nearest_neighbour.hpp"
#include "dfvn/stats/nearest_other.hpp"
#include "dfvn/stats/periodic_neighbours.hpp"

namespace {

using namespace dfvn;

// Seconds for the tree, the index and the queries; `distances` gets every point's nearest distance.
// periodic: on the torus [0,1)^N.
template <int N, int Lanes>
double search(const PointSet& p, nearest_other::NearestRows<N, Lanes> rows, int leaf, bool periodic,
              std::vector<double>& distances) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<std::uint32_t> nearest = nearest_other::nearest_of_every_point<N, Lanes>(
      p, rows, leaf, periodic ? nearest_other::periodic_torus(0.0, 1.0) : nearest_other::Torus{});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  distances.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    distances[i] = periodic ? periodic_distance_between(p, i, nearest[i]) : distance_between(p, i, nearest[i]);
  return seconds;
}

}  // namespace

int main(int argc, char** argv) try {
  const bool periodic = argc > 1 && std::string(argv[1]) == "--periodic";
  if (periodic) --argc, ++argv;
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: nearest_leaf_sizes [--periodic] SET.npy [REPEATS (default 3)]\n");
    return 2;
  }
  const int repeats = argc == 3 ? std::atoi(argv[2]) : 3;
  if (repeats < 1) throw std::invalid_argument("REPEATS must be at least 1");
  std::vector<PointTable> sets = read_point_sets(argv[1], InputFormat::npy);
  if (sets.size() != 1) throw std::invalid_argument("the file holds more than one point set");
  PointSet p{sets[0].dimension, std::move(sets[0].coordinates),
             periodic ? Domain(DomainKind::torus, 0.0, 1.0) : Domain(Box{})};
  const std::vector<int> leaves{16, 24, 32, 48, 64, 96, 128};
  std::vector<double> reference;
  dispatch_dimension(p.dimension, [&]<int N>() {
    const auto row = [&](const char* name, auto rows_of_leaf) {
      std::printf("| %dD | %s |", N, name);
      for (const int leaf : leaves) {
        std::vector<double> seconds;
        for (int r = 0; r < repeats; ++r) {
          std::vector<double> distances;
          seconds.push_back(rows_of_leaf(leaf, distances));
          if (reference.empty()) reference = distances;
          if (distances != reference) throw std::logic_error("a build or leaf size found other nearest distances");
        }
        std::sort(seconds.begin(), seconds.end());
        std::printf(" %.3f |", seconds[seconds.size() / 2]);
      }
      std::printf("\n");
      std::fflush(stdout);
    };
    std::printf("| dim | build |");
    for (const int leaf : leaves) std::printf(" leaf %d (s) |", leaf);
    std::printf("\n| --- | --- |");
    for (std::size_t k = 0; k < leaves.size(); ++k) std::printf(" --- |");
    std::printf("\n");
    row("baseline", [&](int leaf, std::vector<double>& d) { return periodic ? search<N, 4>(p, &nearest_other::baseline::nearest_rows<N, true>, leaf, true, d)
                                  : search<N, 4>(p, &nearest_other::baseline::nearest_rows<N, false>, leaf, false, d); });
#if defined(__x86_64__)
    if (cpu_has_avx2())
      row("AVX2", [&](int leaf, std::vector<double>& d) { return periodic ? search<N, 4>(p, &nearest_other::avx2::nearest_rows<N, true>, leaf, true, d)
                                  : search<N, 4>(p, &nearest_other::avx2::nearest_rows<N, false>, leaf, false, d); });
    if (cpu_has_avx512())
      row("AVX-512", [&](int leaf, std::vector<double>& d) { return periodic ? search<N, 8>(p, &nearest_other::avx512::nearest_rows<N, true>, leaf, true, d)
                                  : search<N, 8>(p, &nearest_other::avx512::nearest_rows<N, false>, leaf, false, d); });
#endif
  });
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "nearest_leaf_sizes: %s: %s\n", argc > 1 ? argv[1] : "", e.what());
  return 1;
}
