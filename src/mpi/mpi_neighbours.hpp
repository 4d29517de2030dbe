// The neighbours of dfvn-sample-mpi's points across ranks (mpi_sampling.hpp): every point moved to the rank
// owning its last coordinate's slab range, the halos that bring each rank the other ranks' points near its
// range, the exact nearest-neighbour distances (in the box or on the torus) and the RDF's pair sums.
//
// Halo: the points of the other ranks whose last coordinate lies within h of a rank's range
// [lo, hi) = [edge(first slab) - h, edge(end slab) + h); on the torus (--periodic) also those a side away,
// so that the halo wraps (the first and last ranks are neighbours) and, with few slabs, spans several
// ranks or the whole torus (then every point is loaded, once). One MPI_Alltoallv sends each point to every
// rank whose halo holds it, once. Points keep their coordinates: the distances (distance_between,
// periodic_distance_between, the kernels that measure the whole set) and the RDF's pair weights are the
// one-process run's bits.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "dfvn/core/point_set.hpp"
#include "dfvn/core/progress.hpp"
#include "dfvn/stats/nearest_neighbour.hpp"
#include "dfvn/stats/radial_distribution.hpp"

namespace dfvn {

// The ranks of a communicator and the contiguous slabs each takes: rank r of P the slabs
// [r S / P, (r + 1) S / P) (with fewer slabs than ranks some take none).
struct RankSlabs {
  MPI_Comm comm;
  int rank = 0, size = 1, slabs = 1;
  RankSlabs(MPI_Comm c, int slab_count);
  int first_slab(int r) const { return static_cast<int>(static_cast<long long>(r) * slabs / size); }
  int rank_of_slab(int s) const;
};

// Records of (index bits, x_0 .. x_{N-1}) exchanged between ranks: out[r] to rank r; returns what every
// rank sent here, in rank order. Throws std::runtime_error past 2^31 values between two ranks.
std::vector<double> all_to_all(MPI_Comm comm, const std::vector<std::vector<double>>& out);

// One method's points over the ranks, each on the rank whose slab range holds its last coordinate (the
// bucket of sample --stream's NearestStream, domain.side / S wide). Constructing it is collective, as is
// every member function below: each rank calls them in the same order.
class OwnedPoints {
 public:
  // `mine`: this rank's generated points, output rows my_first .. my_first + mine.size() - 1; `periodic`:
  // distances on the torus of `domain`.
  OwnedPoints(const RankSlabs& ranks, const PointSet& mine, std::uint64_t my_first, const Domain& domain, bool periodic);

  // Every point's nearest-neighbour distance (minimum-image on the torus), returned to the rank that made
  // the point: (index, distance) for rows my_first .. of `mine`, by index. `first_rows`: the first output
  // row of every rank (P + 1 entries); `total`: the point count. `progress` (rank 0's): the first pass's
  // queries done.
  std::vector<std::pair<std::uint64_t, double>> nearest_distances(const std::vector<std::uint64_t>& first_rows,
                                                                  std::uint64_t total, KnnBackend knn, int threads,
                                                                  const FractionProgress& progress);

  // The RDF of the whole set: this rank's query points (RdfQueries, by output row as in memory) counted
  // against its points and a halo a little wider than r_max, the exact pair sums added over the ranks
  // (reduce_rdf_pair_sums), on the torus when this object is periodic. The same on every rank.
  RdfCurve radial_distribution(const RdfOptions& options, std::uint64_t seed, std::uint64_t total, int threads,
                               const FractionProgress& progress);

 private:
  // Every other rank's owned points within h of this rank's range (wrapping on the torus), each once.
  std::vector<double> halo(double h) const;
  // Whether last coordinate z lies in rank r's range widened by h (or, on the torus, z +- side does).
  bool in_reach(int r, double z, double h) const;
  double edge(int s) const;

  RankSlabs ranks_;
  int n_;
  Domain domain_;
  bool periodic_;
  std::vector<double> owned_;  // records of N + 1 doubles
  double zmin_, zmax_;         // over all ranks' points
};

}  // namespace dfvn
