// The streamed sampling experiment over MPI ranks (dfvn-sample-mpi, issue 28 item 2): the slabs of
// sample --stream (experiment/streamed_sampling.hpp) distributed over the ranks of a communicator, with
// the one-process run's point file and statistics to the last bit, whatever the number of ranks.
//
// Work: S slabs (stream_slab_count's, a divisor of K for cnj and jitter), rank r of P taking the
// contiguous slabs [r S / P, (r + 1) S / P) (with fewer slabs than ranks some ranks make no points and
// only take part in the exchanges). Each rank generates its slabs' points (every point depends only on
// its index, the options and the seed) and keeps them: memory O(n / P + halo) per rank.
//
// Point file: ONE file, written collectively with MPI-IO (MPI_File_write_at_all) at offsets from an
// exclusive prefix sum of the ranks' byte counts (npy and bin: 8 N bytes a point; dat and csv: the text
// of the rank's rows), the header (npy shape, bin count, csv names) by rank 0 once the total count is
// known (drop mode included), to a temporary name beside the file that rank 0 renames once every rank
// reported success. Every rank registers the temporary for removal on SIGTERM/SIGINT (what mpirun sends
// the survivors when a rank dies).
//
// Statistics, exact: sums that the one-process run adds in index order (squared displacements, pair
// differences, Bragg sums, nearest-neighbour distances) are passed from rank to rank (a token along
// ranks 0 .. P-1), each rank adding its rows in index order, so the additions happen in the same order
// as in one process. Order statistics (min, q01, median of the distances; the median displacement
// length) by an exact distributed selection: bisection on the order-preserving 64-bit key of the
// doubles, with MPI_Allreduce'd counts over each rank's sorted values (64 rounds, no gathering).
// Nearest neighbours (mpi_neighbours.hpp): points go (MPI_Alltoallv) to the rank owning their last
// coordinate's slab range; each rank receives (MPI_Alltoallv) the points of the other ranks within a halo h
// of its range, on the torus (--periodic) also those a side away (the halo wraps: the first and last ranks
// are neighbours, and with few slabs it spans several ranks or the whole torus), and h grows until every
// distance found is closer than the loaded region's edge (the one-process rule). --rdf: each rank's query
// points counted against a halo a little wider than r_max, the fixed-point pair sums added exactly over the
// ranks (integers, not floating point: mpi_exact.hpp's reduce_rdf_pair_sums).
//
// Progress (StageProgress, rank 0's): its slabs generated, its first nearest-neighbour pass, its RDF
// queries; the stages of sample --stream.
#pragma once

#include <mpi.h>

#include <functional>
#include <string>
#include <vector>

#include "dfvn/core/progress.hpp"
#include "dfvn/experiment/experiment.hpp"
#include "dfvn/io/point_file.hpp"

namespace dfvn {

// An error that another rank has already reported: the caller exits non-zero without a message.
struct ReportedElsewhere : std::runtime_error {
  ReportedElsewhere() : std::runtime_error("reported by another rank") {}
};

// The slab count for `ranks` ranks: `requested` if given (stream_slab_count's checks: a divisor of K for
// the lattice methods, at most the point count), else the smallest valid count at least both the
// one-process automatic count and `ranks` (for the lattice methods K when no divisor is that large).
int mpi_slab_count(const SampleConfig& config, int requested, int ranks);

// Bytes one rank needs at its peak (about): its share of the largest method's points, kept with their
// exchange buffers, the KD-tree's copy and the distances (measured: 2^21 7D points in 773 MiB, one rank).
double mpi_rank_peak_bytes(const SampleConfig& config, int slabs, int ranks);

// Every check before the run, alike on every rank: config.validate(), stream_refusal, mpi_slab_count, and a
// rank's peak (mpi_rank_peak_bytes) within the memory limit (--max-memory). Returns the slab count;
// throws std::invalid_argument with one line.
int check_mpi_run(const SampleConfig& config, int requested_slabs, int ranks);

// Runs every configured method over the ranks of `comm` in `slabs` slabs, writing each method's points
// to point_path(method) (the same path on every rank; a file, not "-") when point_path is given. The
// results (without points; with the RDF under --rdf) are complete on rank 0, equal to run_streamed_sampling's.
// `progress`: reports of this rank's work (give it on rank 0 only). `fail_rank` >= 0:
// a test hook, that rank exits abruptly once its share of the first point file (or of the first
// method's statistics) is done. Throws std::invalid_argument / std::runtime_error with one line on the
// rank that should report it and ReportedElsewhere on the others.
std::vector<MethodResult> run_mpi_sampling(MPI_Comm comm, const SampleConfig& config, int slabs,
                                           const std::function<std::string(Method)>& point_path, PointFormat format,
                                           const StageProgress& progress = {}, int fail_rank = -1);

}  // namespace dfvn
