// One point file written by every rank of a communicator at once (MPI-IO), each rank's rows at the
// offset of the rows of the ranks below, with the bytes write_point_file gives for the whole set
// (io/point_file.hpp), through a temporary beside the file that rank 0 renames (mpi_sampling.hpp).
#pragma once

#include <mpi.h>

#include <cstdint>
#include <memory>
#include <string>

#include "dfvn/core/point_set.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/point_file.hpp"

namespace dfvn {

class MpiPointFile {
 public:
  // Collective. `path` must be a file (not "-"); the temporary is named from it and rank 0's process id.
  MpiPointFile(MPI_Comm comm, const std::string& path, PointFormat format);
  ~MpiPointFile();  // removes the temporary unless committed
  MpiPointFile(const MpiPointFile&) = delete;
  MpiPointFile& operator=(const MpiPointFile&) = delete;

  // Collective: writes this rank's rows (the rows of the ranks below it come first) into the temporary;
  // throws std::runtime_error (on every rank, through run_everywhere) if the temporary cannot be written.
  void write(const PointSet& rows);
  // Collective, after every rank's write succeeded: rank 0 renames the temporary to the path.
  void commit();

 private:
  MPI_Comm comm_;
  std::string path_, temporary_;
  PointFormat format_;
  int rank_ = 0;
  bool committed_ = false;
  std::unique_ptr<TemporaryRegistration> registration_;
};

}  // namespace dfvn
