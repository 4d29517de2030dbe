// The exact reductions of src/mpi/mpi_exact.hpp under mpirun (any number of ranks): pass_along_ranks
// gives the bits of one sequential sum (where a per-rank partial sum reduced with MPI_SUM differs in the
// last bits, checked too so that the test can tell them apart), select_ranks the values
// std::nth_element gives over all values, duplicates, zeros and negatives included; reduce_rdf_pair_sums
// the fixed-point RDF sums of one process adding every weight (carries across limbs included). Plain main
// (exit status), run by ctest as mpi_exact with 1, 2 and 3 ranks.
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "dfvn/mpi/mpi_exact.hpp"

namespace {

int failures = 0;
int rank = 0, size = 1;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "FAIL (rank %d of %d): %s\n", rank, size, what);
    ++failures;
  }
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  // Every rank makes all the values (the same seed) and keeps its contiguous share.
  constexpr std::size_t kCount = 100003;
  std::mt19937_64 random(7);
  std::lognormal_distribution<double> spread(0.0, 3.0);
  std::vector<double> all(kCount);
  for (std::size_t i = 0; i < kCount; ++i) all[i] = (i % 97 == 0) ? 0.0 : (i % 13 == 0 ? -1.0 : 1.0) * spread(random);
  for (std::size_t i = 0; i < 500; ++i) all[kCount - 1 - i] = all[i];  // duplicates
  const std::size_t first = kCount * static_cast<std::size_t>(rank) / static_cast<std::size_t>(size);
  const std::size_t end = kCount * static_cast<std::size_t>(rank + 1) / static_cast<std::size_t>(size);
  const std::vector<double> mine(all.begin() + static_cast<std::ptrdiff_t>(first), all.begin() + static_cast<std::ptrdiff_t>(end));

  double sequential = 0.0;
  for (double v : all) sequential += v;
  std::vector<double> state{0.0};
  dfvn::pass_along_ranks(MPI_COMM_WORLD, state, [&](std::vector<double>& s) {
    for (double v : mine) s[0] += v;
  });
  check(same_bits(state[0], sequential), "pass_along_ranks: not the bits of the sequential sum");
  if (size > 1) {  // the order matters for these values: a reduction of partial sums differs
    double partial = 0.0, reduced = 0.0;
    for (double v : mine) partial += v;
    MPI_Allreduce(&partial, &reduced, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    check(!same_bits(reduced, sequential), "a partial-sum reduction happens to give the sequential bits: weak values");
  }

  std::vector<double> sorted = mine;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::uint64_t> ranks{0, 1, 17, 1000, kCount / 2 - 1, kCount / 2, kCount - 2, kCount - 1};
  const std::vector<double> got = dfvn::select_ranks(MPI_COMM_WORLD, sorted, ranks);
  std::vector<double> everything = all;
  std::sort(everything.begin(), everything.end());
  for (std::size_t j = 0; j < ranks.size(); ++j) check(same_bits(got[j], everything[ranks[j]]), "select_ranks: a wrong value");
  const double median = dfvn::distributed_median(MPI_COMM_WORLD, sorted, kCount);
  check(same_bits(median, everything[kCount / 2]), "distributed_median (odd count)");

  // RDF pair sums: weights over many binades (every limb carries), each rank adding its share into its own
  // sums; the reduction must give the integers, so the doubles, of one sums adding them all.
  {
    constexpr int kBins = 7;
    constexpr double kLow = 1.0 / 4096.0, kHigh = 4096.0;
    std::mt19937_64 weights(11);
    std::uniform_real_distribution<double> exponent(-12.0, 12.0);
    std::vector<double> w(20011);
    for (double& x : w) x = std::min(kHigh, std::max(kLow, std::exp2(exponent(weights))));
    dfvn::RdfPairSums one(kBins, kLow, kHigh), part = one.empty_copy();
    for (std::size_t i = 0; i < w.size(); ++i) {
      one.add(static_cast<int>(i % kBins), w[i]);
      if (i * static_cast<std::size_t>(size) / w.size() == static_cast<std::size_t>(rank)) part.add(static_cast<int>(i % kBins), w[i]);
    }
    dfvn::reduce_rdf_pair_sums(MPI_COMM_WORLD, part);
    for (int b = 0; b < kBins; ++b) check(same_bits(part.sum(b), one.sum(b)), "reduce_rdf_pair_sums: not one process's sum");
    check(part.words() == one.words(), "reduce_rdf_pair_sums: not one process's integers");
  }

  int any = failures, total = 0;
  MPI_Allreduce(&any, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0) std::printf("mpi_exact (%d ranks): %s\n", size, total ? "FAILED" : "passed");
  MPI_Finalize();
  return total ? 1 : 0;
}
