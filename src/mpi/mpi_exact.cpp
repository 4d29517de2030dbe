#include "dfvn/mpi/mpi_exact.hpp"

#include <algorithm>
#include <cstring>
#include <exception>
#include <limits>
#include <stdexcept>
#include <utility>

#include "dfvn/mpi/mpi_sampling.hpp"
#include "dfvn/stats/nearest_neighbour.hpp"
#include "dfvn/stats/radial_distribution.hpp"

namespace dfvn {

void run_everywhere(MPI_Comm comm, const std::function<void()>& step) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  std::exception_ptr error;
  try {
    step();
  } catch (const ReportedElsewhere&) {
    error = std::current_exception();
    rank = size;  // already reported: not the one to report again
  } catch (...) {
    error = std::current_exception();
  }
  const int mine = error ? rank : size + 1;
  int lowest = 0;
  MPI_Allreduce(&mine, &lowest, 1, MPI_INT, MPI_MIN, comm);
  if (lowest == size + 1) return;
  if (error && lowest == rank) std::rethrow_exception(error);
  throw ReportedElsewhere();
}

void pass_along_ranks(MPI_Comm comm, std::vector<double>& state, const std::function<void(std::vector<double>&)>& add) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const int length = static_cast<int>(state.size());
  if (rank > 0) MPI_Recv(state.data(), length, MPI_DOUBLE, rank - 1, 71, comm, MPI_STATUS_IGNORE);
  add(state);
  if (rank + 1 < size) MPI_Send(state.data(), length, MPI_DOUBLE, rank + 1, 71, comm);
  MPI_Bcast(state.data(), length, MPI_DOUBLE, size - 1, comm);
}

namespace {

// Keys in the order of the doubles: negative values bit-flipped, non-negative ones with the sign bit set.
std::uint64_t key_of(double v) {
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  return (bits >> 63) ? ~bits : bits | (std::uint64_t{1} << 63);
}
double value_of(std::uint64_t key) {
  const std::uint64_t bits = (key >> 63) ? key & ~(std::uint64_t{1} << 63) : ~key;
  double v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

}  // namespace

std::vector<double> select_ranks(MPI_Comm comm, const std::vector<double>& sorted, const std::vector<std::uint64_t>& ranks) {
  std::vector<std::uint64_t> keys(sorted.size());
  for (std::size_t i = 0; i < sorted.size(); ++i) keys[i] = key_of(sorted[i]);
  if (!std::is_sorted(keys.begin(), keys.end())) throw std::logic_error("select_ranks: values not sorted");
  const std::size_t m = ranks.size();
  // For each wanted rank k: the smallest key whose count of keys <= it exceeds k.
  std::vector<std::uint64_t> lo(m, 0), hi(m, std::numeric_limits<std::uint64_t>::max());
  std::vector<unsigned long long> local(m), total(m);
  for (int round = 0; round < 64; ++round) {
    for (std::size_t j = 0; j < m; ++j) {
      const std::uint64_t mid = lo[j] + (hi[j] - lo[j]) / 2;
      local[j] = static_cast<unsigned long long>(std::upper_bound(keys.begin(), keys.end(), mid) - keys.begin());
    }
    MPI_Allreduce(local.data(), total.data(), static_cast<int>(m), MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
    for (std::size_t j = 0; j < m; ++j) {
      const std::uint64_t mid = lo[j] + (hi[j] - lo[j]) / 2;
      if (total[j] > ranks[j]) hi[j] = mid;
      else lo[j] = mid + 1;
    }
  }
  std::vector<double> out(m);
  for (std::size_t j = 0; j < m; ++j) {
    if (lo[j] != hi[j]) throw std::logic_error("select_ranks: the bisection did not close");
    out[j] = value_of(lo[j]);
  }
  return out;
}

std::function<double(std::uint64_t)> distributed_order_statistics(MPI_Comm comm, const std::vector<double>& sorted,
                                                                  std::uint64_t n) {
  // The ranks summarize_nearest_neighbours and a median read (as the one-process stream's order_statistics).
  std::vector<std::uint64_t> ranks = nearest_neighbour_summary_ranks(n);
  std::vector<double> values = select_ranks(comm, sorted, ranks);
  return sorted_at_ranks(std::move(ranks), std::move(values));
}

namespace {

// Set by add_fixed_point when a sum carries out of its top limb (never, by the sums' range).
int fixed_point_overflow = 0;

// inout += in for `len` fixed-point integers of `type` (contiguous 64-bit limbs, least significant first).
void add_fixed_point(void* in, void* inout, int* len, MPI_Datatype* type) {
  int bytes = 0;
  MPI_Type_size(*type, &bytes);
  const int limbs = bytes / static_cast<int>(sizeof(std::uint64_t));
  const auto* a = static_cast<const std::uint64_t*>(in);
  auto* s = static_cast<std::uint64_t*>(inout);
  for (int e = 0; e < *len; ++e, a += limbs, s += limbs)
    if (add_fixed_point_limbs(s, a, limbs)) fixed_point_overflow = 1;
}

}  // namespace

void reduce_rdf_pair_sums(MPI_Comm comm, RdfPairSums& sums) {
  const std::vector<std::uint64_t>& mine = sums.words();
  std::vector<std::uint64_t> total(mine.size(), 0);
  if (!mine.empty()) {
    MPI_Datatype number;
    MPI_Type_contiguous(sums.limbs(), MPI_UINT64_T, &number);
    MPI_Type_commit(&number);
    MPI_Op add;
    MPI_Op_create(&add_fixed_point, 1, &add);
    fixed_point_overflow = 0;
    MPI_Allreduce(mine.data(), total.data(), sums.bins(), number, add, comm);
    MPI_Op_free(&add);
    MPI_Type_free(&number);
  }
  int overflow = fixed_point_overflow, any = 0;
  MPI_Allreduce(&overflow, &any, 1, MPI_INT, MPI_MAX, comm);
  if (any) throw std::logic_error("an RDF pair sum overflowed");
  sums = sums.empty_copy();
  sums.merge_words(total);
}

double distributed_median(MPI_Comm comm, const std::vector<double>& sorted, std::uint64_t n) {
  if (n == 0) return 0.0;
  const auto at = distributed_order_statistics(comm, sorted, n);
  return n % 2 == 1 ? at(n / 2) : 0.5 * (at(n / 2 - 1) + at(n / 2));
}

}  // namespace dfvn
