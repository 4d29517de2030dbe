// Exact reductions over MPI ranks for the distributed sampling run (mpi_sampling.hpp): the order of
// floating-point additions and order statistics independent of the number of ranks.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "dfvn/stats/radial_distribution.hpp"

namespace dfvn {

// Each rank's failure (an exception) made known to every rank: when any rank failed, the lowest failed
// rank rethrows its exception and every other rank throws ReportedElsewhere (mpi_sampling.hpp), so one
// line is printed. Runs `step` on this rank first.
void run_everywhere(MPI_Comm comm, const std::function<void()>& step);

// A running state passed along ranks 0 .. P-1 in order: each rank receives the state of the ranks
// below (as `state`; rank 0 starts from the state it holds), lets `add` update it with its own rows, and
// sends it on; every rank returns the final state. The additions so happen in rank order, as one
// process adds them in index order.
void pass_along_ranks(MPI_Comm comm, std::vector<double>& state, const std::function<void(std::vector<double>&)>& add);

// The values of ascending ranks `ranks` (0-based, each < the total count) in the multiset union of every
// rank's `sorted` values, exactly: bisection on the doubles' order-preserving 64-bit keys with
// MPI_Allreduce'd counts (64 rounds of one reduction). The same on every rank. No NaNs.
std::vector<double> select_ranks(MPI_Comm comm, const std::vector<double>& sorted, const std::vector<std::uint64_t>& ranks);

// The order statistics that summarize_nearest_neighbours and a median read, over `n` values spread over
// the ranks (each rank's `sorted`): a function from rank to value for exactly those ranks.
std::function<double(std::uint64_t)> distributed_order_statistics(MPI_Comm comm, const std::vector<double>& sorted,
                                                                  std::uint64_t n);
double distributed_median(MPI_Comm comm, const std::vector<double>& sorted, std::uint64_t n);

// Every rank's RDF pair sums (the same bins and range everywhere) added exactly: the fixed-point integers
// (RdfPairSums::words) summed limb by limb with carries in an MPI_Allreduce of a user operation, so any
// reduction order gives the same integers; every rank ends with the total. A logic_error on every rank if
// a sum overflowed (the sums leave room for 2^64 weights).
void reduce_rdf_pair_sums(MPI_Comm comm, RdfPairSums& sums);

}  // namespace dfvn
