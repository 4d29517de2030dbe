// The grid search of stats/cell_grid_neighbours.hpp against the KD-tree search (stats/nearest_other.hpp,
// leaves of 64) on the torus [0,1)^N, one thread each, the widest build this CPU runs: for each point set
// (an N-column .npy in [0,1]^N), the median seconds of --repeats runs of each (what `stats --domain torus`
// spends before its summary: the tree or grid built and every point queried) and grid / tree. Both must
// find the same distances, bit for bit (checked). Behind stats/cell_grid_neighbours.cpp's kFewestAxes.
//   build/bench/periodic_grid_vs_tree SET.npy... [--repeats R (default 3)]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "dfvn/core/dimension.hpp"
#include "dfvn/io/point_reader.hpp"
#include "dfvn/stats/cell_grid_neighbours.hpp"
#include "dfvn/stats/nearest_other.hpp"
#include "dfvn/stats/periodic_neighbours.hpp"

namespace {

using namespace dfvn;

template <class F>
double median_seconds(int repeats, F&& f) {
  std::vector<double> seconds;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    f();
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  return seconds[seconds.size() / 2];
}

}  // namespace

int main(int argc, char** argv) try {
  int repeats = 3;
  std::vector<std::string> files;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--repeats" && a + 1 < argc) {
      repeats = std::atoi(argv[++a]);
      if (repeats < 1) throw std::invalid_argument("--repeats must be at least 1");
    } else {
      files.push_back(arg);
    }
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: periodic_grid_vs_tree SET.npy... [--repeats R (default 3)]\n");
    return 2;
  }
  std::printf("| set | dim | points | KD-tree (s) | grid (s) | grid / tree |\n| --- | --- | --- | --- | --- | --- |\n");
  for (const std::string& file : files) {
    std::vector<PointTable> sets = read_point_sets(file, InputFormat::npy);
    if (sets.size() != 1) throw std::invalid_argument(file + " holds more than one point set");
    const PointSet p{sets[0].dimension, std::move(sets[0].coordinates), Domain(DomainKind::torus, 0.0, 1.0)};
    check_in_periodic_box(p);
    dispatch_dimension(p.dimension, [&]<int N>() {
      std::vector<double> tree, grid;
      const double tree_seconds = median_seconds(repeats, [&] {
        tree = nearest_other::nearest_distances<N, true>(p, p.size(), 1, {}, nearest_other::periodic_torus(0.0, 1.0),
                                                         [&](std::size_t i, std::size_t j) { return periodic_distance_between(p, i, j); });
      });
      bool declined = false;
      const double grid_seconds = median_seconds(repeats, [&] {
        auto g = cell_grid::periodic_nearest_distances(p, p.size(), 1, {});
        declined = !g;
        if (g) grid = std::move(*g);
      });
      if (declined) {
        std::printf("| %s | %d | %zu | %.3f | declined | |\n", file.c_str(), N, p.size(), tree_seconds);
      } else {
        if (grid != tree) throw std::logic_error(file + ": the grid and the tree found other distances");
        std::printf("| %s | %d | %zu | %.3f | %.3f | %.2f |\n", file.c_str(), N, p.size(), tree_seconds, grid_seconds,
                    grid_seconds / tree_seconds);
      }
      std::fflush(stdout);
    });
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "periodic_grid_vs_tree: %s\n", e.what());
  return 1;
}
