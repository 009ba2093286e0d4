#include "coupling/output/parcel_writer.h"

#include <hdf5.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "cfd/io/hdf5_file.hpp"
#include "cfd/base/internal_error.hpp"

namespace parcelflow::coupling {

namespace {
// Returns an HDF5 id or status; throws when it signals failure (negative).
hid_t check(hid_t result, const std::string& what, const std::string& path) {
  if (result < 0) throw std::runtime_error("HDF5: " + what + " failed for " + path);
  return result;
}

// An HDF5 id that is closed on scope exit.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  operator hid_t() const { return id_; }
  herr_t close() { return close_(std::exchange(id_, -1)); }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// Writes rows [offset, offset + rows) of a (total x width) dataset, collectively.
void writeRows(hid_t file, const std::string& path, const std::string& name, hid_t type, const void* data,
               long total, long offset, long rows, int width) {
  const int rank = width == 1 ? 1 : 2;
  const hsize_t dims[2] = {static_cast<hsize_t>(total), static_cast<hsize_t>(width)};
  const hsize_t start[2] = {static_cast<hsize_t>(offset), 0};
  const hsize_t count[2] = {static_cast<hsize_t>(rows), static_cast<hsize_t>(width)};
  const std::string what = "writing /" + name;
  Handle file_space(check(H5Screate_simple(rank, dims, nullptr), what, path), H5Sclose);
  Handle set(check(H5Dcreate2(file, name.c_str(), type, file_space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   what, path),
             H5Dclose);
  if (total == 0) return;  // HDF5 1.10 fails a collective write into a dataset without storage
  Handle mem_space(check(H5Screate_simple(rank, count, nullptr), what, path), H5Sclose);
  if (rows > 0) {
    check(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, count, nullptr), what, path);
  } else {
    check(H5Sselect_none(file_space), what, path);
    check(H5Sselect_none(mem_space), what, path);
  }
  Handle xfer(check(H5Pcreate(H5P_DATASET_XFER), what, path), H5Pclose);
  check(H5Pset_dxpl_mpio(xfer, H5FD_MPIO_COLLECTIVE), what, path);
  check(H5Dwrite(set, type, mem_space, file_space, xfer, data), what, path);
}

// Reads the time and the number of parcels of a complete snapshot file (serial, one rank).
std::pair<double, long> readSnapshot(const std::string& path) {
  Handle file(check(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "opening", path), H5Fclose);
  double time = 0.0;
  Handle time_set(check(H5Dopen2(file, "time", H5P_DEFAULT), "opening /time", path), H5Dclose);
  check(H5Dread(time_set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, &time), "reading /time", path);
  Handle positions(check(H5Dopen2(file, "position", H5P_DEFAULT), "opening /position", path), H5Dclose);
  Handle space(check(H5Dget_space(positions), "reading /position", path), H5Sclose);
  hsize_t dims[2] = {0, 0};
  check(H5Sget_simple_extent_dims(space, dims, nullptr), "reading /position", path);
  return {time, static_cast<long>(dims[0])};
}
}  // namespace

ParcelWriter::ParcelWriter(MPI_Comm comm, std::string directory, std::string name)
    : comm_(comm), directory_(std::move(directory)), name_(std::move(name)) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size_);
}

std::string ParcelWriter::fileName(std::size_t index) const { return cfd::seriesFileName(name_, index); }

void ParcelWriter::continueSeries(std::size_t snapshots) {
  times_.assign(snapshots, 0.0);
  counts_.assign(snapshots, 0);
  std::string error;
  if (rank_ == 0) {
    try {
      for (std::size_t i = 0; i < snapshots; ++i)
        std::tie(times_[i], counts_[i]) = readSnapshot(directory_ + "/" + fileName(i));
    } catch (const std::runtime_error& e) {
      error = e.what();
    }
  }
  int failed = !error.empty();
  MPI_Bcast(&failed, 1, MPI_INT, 0, comm_);
  if (failed)
    throw std::runtime_error("cannot continue the parcel series: " + (rank_ == 0 ? error : "see rank 0"));
  MPI_Bcast(times_.data(), static_cast<int>(snapshots), MPI_DOUBLE, 0, comm_);
  MPI_Bcast(counts_.data(), static_cast<int>(snapshots), MPI_LONG, 0, comm_);
  publishIndex();
}

void ParcelWriter::write(double time, const ParcelSnapshot& local) {
  const long n = static_cast<long>(local.dp.size());
  PARCELFLOW_ASSERT(local.x.size() == 3 * local.dp.size() && local.v.size() == 3 * local.dp.size() &&
                            local.np.size() == local.dp.size() && local.type.size() == local.dp.size() &&
                            local.id.size() == local.dp.size(),
                        "ParcelSnapshot arrays of different lengths");
  std::vector<long> counts(size_);
  MPI_Allgather(&n, 1, MPI_LONG, counts.data(), 1, MPI_LONG, comm_);
  long offset = 0, total = 0;
  for (int r = 0; r < size_; ++r) {
    if (r < rank_) offset += counts[r];
    total += counts[r];
  }
  const std::string path = directory_ + "/" + fileName(snapshots());
  {
    Handle fapl(check(H5Pcreate(H5P_FILE_ACCESS), "creating", path), H5Pclose);
    check(H5Pset_fapl_mpio(fapl, comm_, MPI_INFO_NULL), "creating", path);
    Handle file(check(H5Fcreate(cfd::partialPath(path).c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl), "creating",
                      cfd::partialPath(path)),
                H5Fclose);
    writeRows(file, path, "time", H5T_NATIVE_DOUBLE, &time, 1, 0, rank_ == 0 ? 1 : 0, 1);
    writeRows(file, path, "position", H5T_NATIVE_DOUBLE, local.x.data(), total, offset, n, 3);
    writeRows(file, path, "velocity", H5T_NATIVE_DOUBLE, local.v.data(), total, offset, n, 3);
    writeRows(file, path, "dp", H5T_NATIVE_DOUBLE, local.dp.data(), total, offset, n, 1);
    writeRows(file, path, "np", H5T_NATIVE_DOUBLE, local.np.data(), total, offset, n, 1);
    writeRows(file, path, "type", H5T_NATIVE_INT, local.type.data(), total, offset, n, 1);
    writeRows(file, path, "id", H5T_NATIVE_INT64, local.id.data(), total, offset, n, 1);
    std::vector<std::int64_t> vertices(n);
    for (long i = 0; i < n; ++i) vertices[i] = offset + i;
    writeRows(file, path, "connectivity", H5T_NATIVE_INT64, vertices.data(), total, offset, n, 1);
    cfd::publishClosedFile(path, file.close() >= 0, comm_);
  }
  times_.push_back(time);
  counts_.push_back(total);
  publishIndex();
}

void ParcelWriter::publishIndex() const {
  std::string error;
  if (rank_ == 0) {
    try {
      writeXdmf();
    } catch (const std::runtime_error& e) {
      error = e.what();
    }
  }
  int failed = !error.empty();
  MPI_Bcast(&failed, 1, MPI_INT, 0, comm_);
  if (failed) throw std::runtime_error(rank_ == 0 ? error : "cannot write the parcel index (see rank 0)");
}

void ParcelWriter::writeXdmf() const {
  const std::string path = directory_ + "/" + name_ + ".xdmf", partial = path + ".partial";
  {
    std::ofstream x(partial);
    x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
      << "  <Grid Name=\"" << name_ << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (std::size_t i = 0; i < snapshots(); ++i) {
      const std::string n = std::to_string(counts_[i]), file = fileName(i);
      auto item = [&](const std::string& dims, const char* type, int precision, const char* set) {
        x << "      <DataItem Dimensions=\"" << dims << "\" NumberType=\"" << type << "\" Precision=\""
          << precision << "\" Format=\"HDF\">" << file << ":/" << set << "</DataItem>\n";
      };
      auto attribute = [&](const char* set, const char* kind, const std::string& dims, const char* type,
                           int precision) {
        x << "    <Attribute Name=\"" << set << "\" AttributeType=\"" << kind << "\" Center=\"Node\">\n";
        item(dims, type, precision, set);
        x << "    </Attribute>\n";
      };
      x << "   <Grid Name=\"" << name_ << "\" GridType=\"Uniform\">\n    <Time Value=\"" << times_[i]
        << "\"/>\n    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
        << "\" NodesPerElement=\"1\">\n";
      item(n, "Int", 8, "connectivity");
      x << "    </Topology>\n    <Geometry GeometryType=\"XYZ\">\n";
      item(n + " 3", "Float", 8, "position");
      x << "    </Geometry>\n";
      attribute("velocity", "Vector", n + " 3", "Float", 8);
      attribute("dp", "Scalar", n, "Float", 8);
      attribute("np", "Scalar", n, "Float", 8);
      attribute("type", "Scalar", n, "Int", 4);
      attribute("id", "Scalar", n, "Int", 8);
      x << "   </Grid>\n";
    }
    x << "  </Grid>\n </Domain>\n</Xdmf>\n";
    x.close();
    if (!x) throw std::runtime_error("cannot write " + partial);
  }
  if (std::rename(partial.c_str(), path.c_str()) != 0)
    throw std::runtime_error("cannot rename " + partial + " to " + path);
}

}  // namespace parcelflow::coupling
