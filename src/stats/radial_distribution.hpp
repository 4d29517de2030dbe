// Radial distribution function g(r) of a point set in its domain: periodic on the torus, with
// translation edge correction in the cube and the ball.
#pragma once

#include <cstdint>
#include <vector>

#include "dfvn/core/progress.hpp"
#include "dfvn/core/point_set.hpp"

namespace dfvn {

struct RdfOptions {
  double r_max = 0.0;  // 0: 2.5 mean spacings, 2.5 (volume / points)^(1/N)
  int bins = 50;
  // Query points: all when the set is no larger, otherwise a seeded random subset of about this many
  // (each query still counts its pairs with every other point). 0: all points.
  std::uint64_t max_queries = 20000;

  void validate() const;  // throws std::invalid_argument naming the option
};

struct RdfCurve {
  std::vector<double> r;  // bin centres
  std::vector<double> g;
  double r_max = 0.0;
  std::uint64_t queries = 0;
};

// g(r) = V^2 / (q (n - 1)) * sum over ordered pairs (i in queries, j != i) with |x_i - x_j| in the bin
// of w_ij, divided by the N-ball shell volume of the bin, V the volume of the set's domain: each set is
// normalised by its own intensity n / V in the domain it fills (PointSet::domain; a lattice set's is the
// box its cells fill, LatticeSpec::cells). w_ij = 1 / |W intersect (W + x_i - x_j)| is the translation
// edge correction (Ohser and Stoyan 1981): prod_a (L - |x_ia - x_ja|) for the cube of side L, the lens
// of two balls of radius R at distance |x_i - x_j| for the ball. For uniform random points E[g(r)] = 1
// at every r, edges and all. (The paper's script divides by shell volume x n x n on a unit volume
// without correction, so its curves tend to 0.5 and sag.) The torus: the pairs at minimum-image
// distance, w_ij = 1 (it has no edge), r_max below half the side (0: 2.5 mean spacings, capped at 0.499
// side); every coordinate must lie in the box. The sphere is refused.
// Independent of thread count and of the order pairs are found in: the weights are summed exactly
// (RdfPairSums) and rounded once. `progress`: query points done over query points.
RdfCurve radial_distribution(const PointSet& points, const RdfOptions& options, std::uint64_t seed, int threads,
                             const FractionProgress& progress = {});

// The pieces of radial_distribution, for callers that count a set's pairs in parts (sample --stream: each
// slab's query points against the slab and a halo holding every point within r_max of them). The curve
// depends only on the pair sums, which are exact, so parts counted in any order give the same bits.

// sum += addend for one fixed-point integer of `limbs` 64-bit limbs, least significant first (RdfPairSums'
// bins, and their reduction over MPI ranks); true if it carried out of the top limb.
bool add_fixed_point_limbs(std::uint64_t* sum, const std::uint64_t* addend, int limbs);

// Every bin's sum of pair weights as a fixed-point integer wide enough for every weight of the run (the
// range given) and 2^64 of them: additions in any order (threads, slabs) give the same sum, rounded to the
// nearest double once, by sum().
class RdfPairSums {
 public:
  RdfPairSums() = default;
  // Weights in [min_weight, max_weight] (positive, finite); a weight outside is a std::logic_error.
  RdfPairSums(int bins, double min_weight, double max_weight);
  // An empty sum of the same bins and range.
  RdfPairSums empty_copy() const;
  void add(int bin, double weight);
  void merge(const RdfPairSums& other);  // same bins and range
  double sum(int bin) const;             // correctly rounded
  int bins() const { return bins_; }
  // The fixed-point integers themselves, for exact reductions beyond one process (dfvn-sample-mpi adds
  // them over ranks as integers, mpi/mpi_exact.hpp): bins() numbers of limbs() 64-bit limbs each, least
  // significant limb first, and the merge of such words from a sum of the same bins and range.
  int limbs() const { return limbs_; }
  const std::vector<std::uint64_t>& words() const { return limb_; }
  void merge_words(const std::vector<std::uint64_t>& words);  // words.size() == words().size()

 private:
  int bins_ = 0, limbs_ = 0, low_exponent_ = 0;  // value = sum_k limb_k 2^(64 k + low_exponent_)
  std::vector<std::uint64_t> limb_;               // bins_ x limbs_
};

// What an RDF of `points` points in `domain` counts: r_max (the default 2.5 mean spacings, capped as
// RdfOptions says), the bins, the torus or the cube. Throws std::invalid_argument as radial_distribution.
struct RdfPlan {
  int dimension = 0;
  Domain domain;
  std::uint64_t points = 0;
  double r_max = 0.0;
  int bins = 0;
  bool periodic = false;  // domain.periodic()
  RdfPairSums empty_sums() const;  // for this plan's weights
};
RdfPlan plan_radial_distribution(int dimension, const Domain& domain, std::uint64_t points, const RdfOptions& options);

// |B intersect (B + d)| for a ball B of radius R in N dimensions and |d| = distance < 2R: the lens of
// two balls, 2 V_{N-1} R^N J_N(acos(distance / 2R)), J_N(phi) = integral_0^phi sin^N, by its recursion.
double ball_overlap_volume(int dimension, double radius, double distance);

// Whether point `index` of a set of `points` is one of the RDF's query points (by index: all of them when
// options.max_queries is 0 or at least `points`, else a seeded subset of about max_queries).
class RdfQueries {
 public:
  RdfQueries(const RdfOptions& options, std::uint64_t seed, std::uint64_t points);
  bool operator()(std::uint64_t index) const;

 private:
  bool all_ = true;
  double keep_ = 1.0;
  std::uint64_t seed_ = 0;
};

// Adds to `sums` the pairs (i, j) of `set` with i one of the rows `queries` and j any other row within
// plan.r_max of x_i (on the torus: of x_i or one of its images in the box set.domain, which must be
// plan.domain). Every point within r_max of a query must be in `set`; coordinates at unit scale
// (domain_scale and coordinate_scale 1). Independent of thread count. `progress`: queries done.
void count_rdf_pairs(const PointSet& set, const std::vector<std::uint32_t>& queries, const RdfPlan& plan,
                     RdfPairSums& sums, int threads, const FractionProgress& progress = {});

// g(r) from the pair sums of `queries` query points.
RdfCurve finish_radial_distribution(const RdfPlan& plan, const RdfPairSums& sums, std::uint64_t queries);

// Throws std::invalid_argument unless every g(r) of an RDF with this r_max (at most 0.999 side) and
// number of bins is finite for points in a cube of this side: a bin too narrow has a shell volume
// that underflows, and --rdf-max 1e-300 gave NaN.
void check_rdf_resolution(int dimension, double side, double r_max, int bins);

}  // namespace dfvn
