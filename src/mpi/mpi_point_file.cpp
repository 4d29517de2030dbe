#include "dfvn/mpi/mpi_point_file.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

#include <fmt/format.h>

#include "dfvn/mpi/mpi_exact.hpp"

namespace dfvn {

namespace {

std::string mpi_error_text(int code) {
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  return std::string(text, static_cast<std::size_t>(length));
}

// The rows' bytes as write_point_file writes them, without the file's header.
std::string row_bytes(const PointSet& rows, PointFormat format) {
  switch (format) {
    case PointFormat::npy:
    case PointFormat::bin: {
      std::string bytes(rows.coordinates.size() * sizeof(double), '\0');
      if (!bytes.empty()) std::memcpy(bytes.data(), rows.coordinates.data(), bytes.size());
      return bytes;
    }
    case PointFormat::dat: {
      std::ostringstream out;
      write_points_dat(out, rows);
      return out.str();
    }
    case PointFormat::csv: {
      std::ostringstream out, header;
      write_points_csv(out, rows);
      write_points_csv(header, PointSet{rows.dimension, {}, rows.domain});
      return out.str().substr(header.str().size());
    }
  }
  return {};
}

std::string header_bytes(PointFormat format, int dimension, std::uint64_t count) {
  std::ostringstream out;
  switch (format) {
    case PointFormat::npy: write_npy_header(out, fmt::format("{}, {}", count, dimension)); break;
    case PointFormat::bin: {
      if (count > std::numeric_limits<std::uint32_t>::max())
        throw std::invalid_argument("UTK's .bin holds at most 2^32 - 1 points a set");
      const auto n = static_cast<std::uint32_t>(count);
      out.write(reinterpret_cast<const char*>(&n), 4);
      break;
    }
    case PointFormat::csv: write_points_csv(out, PointSet{dimension, {}, Box{}}); break;
    case PointFormat::dat: break;
  }
  return out.str();
}

}  // namespace

MpiPointFile::MpiPointFile(MPI_Comm comm, const std::string& path, PointFormat format)
    : comm_(comm), path_(path), format_(format) {
  MPI_Comm_rank(comm_, &rank_);
  long long pid = rank_ == 0 ? static_cast<long long>(::getpid()) : 0;
  MPI_Bcast(&pid, 1, MPI_LONG_LONG, 0, comm_);
  const std::filesystem::path p(path_);
  temporary_ = (p.parent_path() / fmt::format(".{}.dfvn-mpi.{}", p.filename().string(), pid)).string();
  registration_ = std::make_unique<TemporaryRegistration>(temporary_, TemporaryRegistration::Kind::file);
}

MpiPointFile::~MpiPointFile() {
  if (!committed_ && rank_ == 0) std::remove(temporary_.c_str());
}

void MpiPointFile::write(const PointSet& rows) {
  int size = 1;
  MPI_Comm_size(comm_, &size);
  const std::string bytes = row_bytes(rows, format_);
  unsigned long long count = rows.size(), total = 0, mine = bytes.size(), below = 0;
  MPI_Allreduce(&count, &total, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm_);
  MPI_Exscan(&mine, &below, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm_);
  if (rank_ == 0) below = 0;  // MPI_Exscan leaves rank 0's result undefined
  std::string header;
  run_everywhere(comm_, [&] { header = header_bytes(format_, rows.dimension, total); });
  MPI_File file;
  int code = MPI_File_open(comm_, temporary_.c_str(), MPI_MODE_CREATE | MPI_MODE_WRONLY, MPI_INFO_NULL, &file);
  run_everywhere(comm_, [&] {
    if (code != MPI_SUCCESS)
      throw std::runtime_error(fmt::format("cannot write {}: {}", path_, mpi_error_text(code)));
  });
  // Blocks of at most 1 GiB, as many on every rank (write_at_all is collective).
  constexpr std::uint64_t kBlock = std::uint64_t{1} << 30;
  const std::string& first = rank_ == 0 ? header : bytes;
  const std::uint64_t local = rank_ == 0 ? header.size() + bytes.size() : bytes.size();
  unsigned long long blocks = (local + kBlock - 1) / kBlock, most = 0;
  MPI_Allreduce(&blocks, &most, 1, MPI_UNSIGNED_LONG_LONG, MPI_MAX, comm_);
  // Rank 0 writes its header and its rows as one buffer.
  std::string joined;
  if (rank_ == 0) joined = header + bytes;
  const std::string& data = rank_ == 0 ? joined : first;
  const std::uint64_t offset = rank_ == 0 ? 0 : header.size() + below;
  int failed = 0;
  for (unsigned long long b = 0; b < most; ++b) {
    const std::uint64_t at = std::min<std::uint64_t>(b * kBlock, data.size());
    const std::uint64_t n = std::min<std::uint64_t>(kBlock, data.size() - at);
    code = MPI_File_write_at_all(file, static_cast<MPI_Offset>(offset + at), data.data() + at, static_cast<int>(n),
                                 MPI_BYTE, MPI_STATUS_IGNORE);
    if (code != MPI_SUCCESS) failed = code;
  }
  code = MPI_File_close(&file);
  if (code != MPI_SUCCESS && !failed) failed = code;
  run_everywhere(comm_, [&] {
    if (failed) throw std::runtime_error(fmt::format("cannot write {}: {}", path_, mpi_error_text(failed)));
  });
}

void MpiPointFile::commit() {
  // Every rank has written its share (a rank that died never gets here, and the others wait in this
  // reduction until mpirun stops them: the signal removes the temporary).
  run_everywhere(comm_, [] {});
  int ok = 1;
  if (rank_ == 0) {
    std::error_code error;
    std::filesystem::rename(temporary_, path_, error);
    ok = !error;
  }
  run_everywhere(comm_, [&] {
    if (!ok) throw std::runtime_error(fmt::format("cannot rename the written points to {}", path_));
  });
  committed_ = true;
}

}  // namespace dfvn
