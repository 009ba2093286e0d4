#include "field_writer.hpp"

#include <hdf5.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "config_error.hpp"
#include "internal_error.hpp"

namespace parcelflow::cfd {

namespace {
// One parallel HDF5 file open for writing; closes on scope exit.
class H5File {
 public:
  H5File(const std::string& path, MPI_Comm comm) {
    const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL);
    id_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
    H5Pclose(fapl);
    if (id_ < 0) throw ConfigError("cannot create HDF5 file " + path + " (does the folder exist?)");
  }
  ~H5File() { H5Fclose(id_); }
  H5File(const H5File&) = delete;
  H5File& operator=(const H5File&) = delete;

  // Writes rows [offset, offset + rows) of a (totalRows x width) dataset, collectively.
  template <class T>
  void write(const std::string& name, hid_t type, const T* data, long totalRows, long offset,
             long rows, int width) {
    hsize_t dims[2] = {static_cast<hsize_t>(totalRows), static_cast<hsize_t>(width)};
    const int rank = width == 1 ? 1 : 2;
    const hid_t fileSpace = H5Screate_simple(rank, dims, nullptr);
    const hid_t set = H5Dcreate2(id_, name.c_str(), type, fileSpace, H5P_DEFAULT, H5P_DEFAULT,
                                 H5P_DEFAULT);
    hsize_t start[2] = {static_cast<hsize_t>(offset), 0};
    hsize_t count[2] = {static_cast<hsize_t>(rows), static_cast<hsize_t>(width)};
    const hid_t memSpace = H5Screate_simple(rank, count, nullptr);
    if (rows > 0) {
      H5Sselect_hyperslab(fileSpace, H5S_SELECT_SET, start, nullptr, count, nullptr);
    } else {
      H5Sselect_none(fileSpace);
      H5Sselect_none(memSpace);
    }
    const hid_t dxpl = H5Pcreate(H5P_DATASET_XFER);
    H5Pset_dxpl_mpio(dxpl, H5FD_MPIO_COLLECTIVE);
    const herr_t status = H5Dwrite(set, type, memSpace, fileSpace, dxpl, data);
    PARCELFLOW_CFD_ASSERT(status >= 0, "HDF5 write of " + name + " failed");
    H5Pclose(dxpl);
    H5Sclose(memSpace);
    H5Sclose(fileSpace);
    H5Dclose(set);
  }

 private:
  hid_t id_;
};

std::string baseName(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}
}  // namespace

FieldWriter::FieldWriter(const Mesh& mesh, std::string directory, std::string name)
    : mesh_(mesh), directory_(std::move(directory)), name_(std::move(name)) {
  long owned = mesh_.nOwnedCells();
  MPI_Exscan(&owned, &offset_, 1, MPI_LONG, MPI_SUM, mesh_.comm());
  if (mesh_.rank() == 0) offset_ = 0;  // MPI_Exscan leaves rank 0's result undefined
  writeMesh();
}

void FieldWriter::writeMesh() {
  const int n = mesh_.nOwnedCells();
  const Vec3 h = mesh_.background().spacing();
  // Corners in VTK hexahedron order.
  static const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                   {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  std::vector<double> points(static_cast<std::size_t>(n) * 24);
  std::vector<long long> cells(static_cast<std::size_t>(n) * 8), ids(n);
  for (int c = 0; c < n; ++c) {
    const Vec3 lo = mesh_.cellCentre(c) - 0.5 * h;
    for (int k = 0; k < 8; ++k) {
      for (int d = 0; d < 3; ++d) points[(8 * c + k) * 3 + d] = lo[d] + corner[k][d] * h[d];
      cells[8 * c + k] = 8 * (offset_ + c) + k;
    }
    ids[c] = mesh_.globalId(c);
  }
  const long total = mesh_.nGlobalCells();
  H5File file(directory_ + "/" + name_ + "_mesh.h5", mesh_.comm());
  file.write("points", H5T_NATIVE_DOUBLE, points.data(), 8 * total, 8 * offset_, 8L * n, 3);
  file.write("cells", H5T_NATIVE_LLONG, cells.data(), total, offset_, n, 8);
  file.write("global_id", H5T_NATIVE_LLONG, ids.data(), total, offset_, n, 1);
}

void FieldWriter::addScalar(const std::string& name, const ScalarField& field) {
  scalars_.emplace_back(name, &field);
}

void FieldWriter::addVector(const std::string& name, const VectorField& field) {
  vectors_.emplace_back(name, &field);
}

void FieldWriter::write(double time) {
  char index[16];
  std::snprintf(index, sizeof index, "%06zu", snapshots_.size());
  const std::string path = directory_ + "/" + name_ + "_" + index + ".h5";
  const int n = mesh_.nOwnedCells();
  const long total = mesh_.nGlobalCells();
  Snapshot snap{time, baseName(path), {}, {}};
  {
    H5File file(path, mesh_.comm());
    const double t[1] = {time};
    file.write("time", H5T_NATIVE_DOUBLE, t, 1, 0, mesh_.rank() == 0 ? 1 : 0, 1);
    for (const auto& [name, field] : scalars_) {
      PARCELFLOW_CFD_ASSERT(static_cast<int>(field->size()) >= n, "short field " + name);
      file.write(name, H5T_NATIVE_DOUBLE, field->data(), total, offset_, n, 1);
      snap.scalars.push_back(name);
    }
    for (const auto& [name, field] : vectors_) {
      PARCELFLOW_CFD_ASSERT(static_cast<int>(field->size()) >= n, "short field " + name);
      file.write(name, H5T_NATIVE_DOUBLE, (*field)[0].data(), total, offset_, n, 3);
      snap.vectors.push_back(name);
    }
  }
  scalars_.clear();
  vectors_.clear();
  snapshots_.push_back(snap);
  if (mesh_.rank() == 0) writeXdmf();
}

void FieldWriter::writeXdmf() const {
  const long n = mesh_.nGlobalCells();
  const std::string meshFile = name_ + "_mesh.h5";
  std::ofstream x(directory_ + "/" + name_ + ".xdmf");
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
    << "  <Grid Name=\"" << name_ << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  auto item = [&](const std::string& dims, const char* type, const std::string& where) {
    x << "      <DataItem Dimensions=\"" << dims << "\" NumberType=\"" << type
      << "\" Precision=\"8\" Format=\"HDF\">" << where << "</DataItem>\n";
  };
  for (const auto& s : snapshots_) {
    x << "   <Grid Name=\"gas\" GridType=\"Uniform\">\n    <Time Value=\"" << s.time << "\"/>\n"
      << "    <Topology TopologyType=\"Hexahedron\" NumberOfElements=\"" << n << "\">\n";
    item(std::to_string(n) + " 8", "Int", meshFile + ":/cells");
    x << "    </Topology>\n    <Geometry GeometryType=\"XYZ\">\n";
    item(std::to_string(8 * n) + " 3", "Float", meshFile + ":/points");
    x << "    </Geometry>\n";
    for (const auto& name : s.scalars) {
      x << "    <Attribute Name=\"" << name << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n";
      item(std::to_string(n), "Float", s.file + ":/" + name);
      x << "    </Attribute>\n";
    }
    for (const auto& name : s.vectors) {
      x << "    <Attribute Name=\"" << name << "\" AttributeType=\"Vector\" Center=\"Cell\">\n";
      item(std::to_string(n) + " 3", "Float", s.file + ":/" + name);
      x << "    </Attribute>\n";
    }
    x << "   </Grid>\n";
  }
  x << "  </Grid>\n </Domain>\n</Xdmf>\n";
}

}  // namespace parcelflow::cfd
