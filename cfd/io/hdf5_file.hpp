#pragma once
// A parallel HDF5 file (MPI-IO driver) for collective writes of row blocks, and a serial reader of whole
// datasets. Every failure throws std::runtime_error naming the file and the dataset: a full disk or an
// unwritable folder is never silent. Used by the field writer and the gas checkpoint.
#include <hdf5.h>
#include <mpi.h>

#include <cerrno>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace parcelflow::cfd {

// An HDF5 file is written as PATH.partial and renamed to PATH once closed on every rank, so that a run
// killed while writing (SIGKILL, a node failure) leaves no file under the real name that does not open.
inline std::string partialPath(const std::string& path) { return path + ".partial"; }
// The output series of a coupled run (NAME_000012.h5 and NAME.xdmf in its output folder): the names the
// writers are made with and the restart's check of an output folder looks for.
namespace series {
inline constexpr const char* fields = "fields";
inline constexpr const char* parcels = "parcels";
inline constexpr const char* averages = "averages";
}  // namespace series
// The file of snapshot `index` of an output series: NAME_000012.h5, the one spelling the writers and the
// restart's check of an output folder share.
inline std::string seriesFileName(const std::string& name, std::size_t index) {
  char digits[32];  // room for any size_t
  std::snprintf(digits, sizeof digits, "_%06zu.h5", index);
  return name + digits;
}
// Collective, after each rank closed its handle of partialPath(path) (`closed_here`: whether that worked):
// throws on every rank if any rank failed to close, else rank 0 renames partialPath(path) to path (throws on
// every rank if that fails). (Inline: the parcel writer's library uses it without the gas solver's.)
inline void publishClosedFile(const std::string& path, bool closed_here, MPI_Comm comm) {
  int closed = closed_here ? 1 : 0, all_closed = 0;
  MPI_Allreduce(&closed, &all_closed, 1, MPI_INT, MPI_MIN, comm);
  if (!all_closed) throw std::runtime_error("HDF5: closing failed for " + partialPath(path));
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int error = 0;
  if (rank == 0 && std::rename(partialPath(path).c_str(), path.c_str()) != 0) error = errno;
  MPI_Bcast(&error, 1, MPI_INT, 0, comm);
  if (error) throw std::runtime_error("cannot rename " + partialPath(path) + " to " + path + ": " + std::strerror(error));
}

class Hdf5Writer {
 public:
  // creates (truncates) partialPath(path), collectively; close() publishes it as `path`
  Hdf5Writer(const std::string& path, MPI_Comm comm);
  ~Hdf5Writer();
  Hdf5Writer(const Hdf5Writer&) = delete;
  Hdf5Writer& operator=(const Hdf5Writer&) = delete;

  // Writes rows [offset, offset + rows) of a (totalRows x width) dataset, collectively.
  void write(const std::string& name, const double* data, long totalRows, long offset, long rows, int width);
  void write(const std::string& name, const long long* data, long totalRows, long offset, long rows, int width);
  // Writes this rank's rows at the given row indices of a (totalRows x width) dataset, collectively (a
  // layout that does not depend on how the rows are spread over ranks).
  void writeAt(const std::string& name, const double* data, long totalRows, const std::vector<long>& rowIndex,
               int width);
  void writeAt(const std::string& name, const long long* data, long totalRows, const std::vector<long>& rowIndex,
               int width);
  void attribute(const std::string& name, const std::string& value);  // a string on the root group
  void attribute(const std::string& name, double value);
  // Closes the file; throws if HDF5 could not flush it (before that, the file may be incomplete).
  void close();

 private:
  void writeTyped(const std::string& name, hid_t type, const void* data, long totalRows, long offset, long rows,
                  int width);
  // Collective write of the selected elements; closes the dataset and both dataspaces.
  void writeSelection(const std::string& name, hid_t set, hid_t type, hid_t memSpace, hid_t fileSpace,
                      const void* data);
  void writeAtTyped(const std::string& name, hid_t type, const void* data, long totalRows,
                    const std::vector<long>& rowIndex, int width);
  std::string path_;
  MPI_Comm comm_;
  hid_t id_ = -1;
};

class Hdf5Reader {
 public:
  explicit Hdf5Reader(const std::string& path);  // this rank alone, read-only
  ~Hdf5Reader();
  Hdf5Reader(const Hdf5Reader&) = delete;
  Hdf5Reader& operator=(const Hdf5Reader&) = delete;

  std::vector<double> doubles(const std::string& name) const;  // a whole dataset, row-major
  std::vector<long long> integers(const std::string& name) const;
  bool hasDataset(const std::string& name) const;
  std::string textAttribute(const std::string& name) const;
  double numberAttribute(const std::string& name) const;

 private:
  std::string path_;
  hid_t id_ = -1;
};

// Rows of this rank in rank order: the sum of `rows` over the lower ranks.
long rowOffset(long rows, MPI_Comm comm);

}  // namespace parcelflow::cfd
