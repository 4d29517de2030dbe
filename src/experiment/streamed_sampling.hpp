// The sampling experiment in slabs (sample --stream): point sets larger than memory, written and measured
// a slab at a time, with the bytes and statistics of the in-memory run (experiment/experiment.hpp).
//
// Generation: slabs of consecutive point indices. The lattice methods (cnj, jitter) cut the K^N lattice
// into S slabs of K/S whole layers of its slowest axis (the last coordinate: points are numbered axis 0
// fastest, so a slab is a contiguous block of the output); random and Sobol, which are addressable by
// index, into S blocks of ceil(n/S) indices. Every point depends only on its index (CNJ: on its site, the
// options and the seed), so a slab gives the whole run's rows. Each slab is appended to the point file
// (npy and bin: the final shape first) and its displacement sums are added in index order (the neighbour
// pairs across a slab boundary with the previous slab's last layer kept).
//
// Statistics: the points are also spilled to S temporary buckets by their last coordinate; each bucket is
// measured with a halo of the points within one mean spacing of it from the others (a KD-tree over the
// bucket and its halo, queried at the bucket's points only: stats' *_of_first); a point whose nearest
// neighbour found is farther than the halo's edge is measured again against the points beyond the halo
// within that distance of it in the last coordinate, so the distances are exact. They go to a temporary
// file by point index, and are then summed in index order and sorted per slab: min, q01 and the median
// are exact selections over those sorted runs. --periodic: the same with minimum-image distances on the
// torus of the box, the halo wrapping around (the first and last buckets are neighbours; with one or two
// buckets each point is loaded once). --rdf: each bucket's query points (chosen by point index, as in
// memory) counted against a halo a little wider than r_max, over as many buckets as it spans; the pair
// sums are exact integers of fixed point (stats/radial_distribution.hpp), so the curve is the in-memory
// one to the bit.
//
// Memory is O(slab + halo); the temporaries (streamed_temporary_bytes: point count x (N + 4) x 8 bytes, 8
// more for cnj and jitter) go to a folder of $TMPDIR, refused up front when it has not that much free
// (stream_temporaries_refusal), and removed on every exit and on SIGINT, SIGTERM and SIGHUP at any moment
// (the folder is registered with io/atomic_file.hpp's cleanup before it is made). Not streamed: pds, jitter-matched, halton, lhs, --domain ball, --on sphere,
// more than one realization (stream_refusal says which).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "dfvn/experiment/experiment.hpp"
#include "dfvn/io/point_file.hpp"

namespace dfvn {

// Why `config` cannot run streamed (one line naming the option), or empty when it can.
std::string stream_refusal(const SampleConfig& config);

// The slab count: `requested` (0: the smallest count whose slabs hold at most kStreamSlabPoints points; for
// the lattice methods a divisor of K). Throws std::invalid_argument when a lattice method is asked for a
// count that does not divide K, or for more slabs than points.
inline constexpr std::uint64_t kStreamSlabPoints = std::uint64_t{1} << 22;
int stream_slab_count(const SampleConfig& config, int requested);

// Rows [first, first + rows) of a streamable method (cnj, jitter, random, sobol): its accepted points in index
// order, its displacements (lattice methods: every traced row) and its counts. Every point depends only on
// its index, so any cut into ranges gives the same rows (sample --stream's slabs, dfvn-sample-mpi's ranks).
struct Slab {
  PointSet points;
  std::vector<double> displacements;
  std::uint64_t dropped = 0, skipped = 0, retraced = 0, kept = 0;
  double trace_time = 0.0, field_frequency = 0.0;
};
Slab generate_slab(const SampleConfig& config, const MethodPlan& plan, std::uint64_t first, std::uint64_t rows);

// Bytes a streamed run needs at its peak (about): the largest bucket with its halo, measured.
double streamed_peak_bytes(const SampleConfig& config, int slabs);

// Bytes of temporary files a streamed run keeps in $TMPDIR at its peak (the largest method's).
double streamed_temporary_bytes(const SampleConfig& config);

// Why a streamed run in `slabs` slabs cannot keep its temporary files, in one line naming the size and
// $TMPDIR's free space (statvfs), or the open files it needs and the limit (RLIMIT_NOFILE); empty when
// it can. run_streamed_sampling refuses with it before anything is written.
std::string stream_temporaries_refusal(const SampleConfig& config, int slabs);

// What helps when a streamed run in `slabs` slabs needs more than `limit` bytes, for the refusal: "raise
// --slabs" only when a larger slab count the run may take would fit; "lower --rdf-max" when the RDF's halo
// is what does not fit (the run without it would); else only "raise --max-memory GIB".
std::string streamed_memory_advice(const SampleConfig& config, int slabs, double limit);

// Runs every configured method in `slabs` slabs (stream_slab_count's), writing each method's points to
// point_path(method) in `format` when point_path is given. Returns the results without points, as
// run_sampling(config, false) does (the same statistics to the last bit).
std::vector<MethodResult> run_streamed_sampling(const SampleConfig& config, int slabs,
                                                const std::function<std::string(Method)>& point_path,
                                                PointFormat format, const StageProgress& progress = {});

}  // namespace dfvn
