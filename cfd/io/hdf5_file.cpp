#include "cfd/io/hdf5_file.hpp"

#include <stdexcept>

namespace parcelflow::cfd {

namespace {

void check(bool ok, const std::string& what, const std::string& path) {
  if (!ok) throw std::runtime_error("HDF5: " + what + " failed for " + path);
}

}  // namespace

long rowOffset(long rows, MPI_Comm comm) {
  long offset = 0;
  MPI_Exscan(&rows, &offset, 1, MPI_LONG, MPI_SUM, comm);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  return rank == 0 ? 0 : offset;  // MPI_Exscan leaves rank 0's result undefined
}

Hdf5Writer::Hdf5Writer(const std::string& path, MPI_Comm comm) : path_(path), comm_(comm) {
  const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL);
  id_ = H5Fcreate(partialPath(path).c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  H5Pclose(fapl);
  check(id_ >= 0, "creating the file (does the folder exist and is it writable?)", partialPath(path));
}

Hdf5Writer::~Hdf5Writer() {
  if (id_ >= 0) H5Fclose(id_);
}

void Hdf5Writer::close() {
  const bool closed = H5Fclose(id_) >= 0;
  id_ = -1;
  publishClosedFile(path_, closed, comm_);  // every rank throws, or none
}

void Hdf5Writer::write(const std::string& name, const double* data, long totalRows, long offset, long rows,
                       int width) {
  writeTyped(name, H5T_NATIVE_DOUBLE, data, totalRows, offset, rows, width);
}

void Hdf5Writer::write(const std::string& name, const long long* data, long totalRows, long offset, long rows,
                       int width) {
  writeTyped(name, H5T_NATIVE_LLONG, data, totalRows, offset, rows, width);
}

void Hdf5Writer::writeSelection(const std::string& name, hid_t set, hid_t type, hid_t memSpace, hid_t fileSpace,
                                const void* data) {
  const hid_t dxpl = H5Pcreate(H5P_DATASET_XFER);
  H5Pset_dxpl_mpio(dxpl, H5FD_MPIO_COLLECTIVE);
  const herr_t status = set < 0 ? -1 : H5Dwrite(set, type, memSpace, fileSpace, dxpl, data);
  H5Pclose(dxpl);
  H5Sclose(memSpace);
  H5Sclose(fileSpace);
  if (set >= 0) H5Dclose(set);
  check(status >= 0, "writing dataset " + name, path_);
}

void Hdf5Writer::writeTyped(const std::string& name, hid_t type, const void* data, long totalRows, long offset,
                            long rows, int width) {
  hsize_t dims[2] = {static_cast<hsize_t>(totalRows), static_cast<hsize_t>(width)};
  const int rank = width == 1 ? 1 : 2;
  const hid_t fileSpace = H5Screate_simple(rank, dims, nullptr);
  const hid_t set = H5Dcreate2(id_, name.c_str(), type, fileSpace, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  hsize_t start[2] = {static_cast<hsize_t>(offset), 0};
  hsize_t count[2] = {static_cast<hsize_t>(rows), static_cast<hsize_t>(width)};
  const hid_t memSpace = H5Screate_simple(rank, count, nullptr);
  if (rows > 0) {
    H5Sselect_hyperslab(fileSpace, H5S_SELECT_SET, start, nullptr, count, nullptr);
  } else {
    H5Sselect_none(fileSpace);
    H5Sselect_none(memSpace);
  }
  writeSelection(name, set, type, memSpace, fileSpace, data);
}

void Hdf5Writer::writeAt(const std::string& name, const double* data, long totalRows,
                         const std::vector<long>& rowIndex, int width) {
  writeAtTyped(name, H5T_NATIVE_DOUBLE, data, totalRows, rowIndex, width);
}

void Hdf5Writer::writeAt(const std::string& name, const long long* data, long totalRows,
                         const std::vector<long>& rowIndex, int width) {
  writeAtTyped(name, H5T_NATIVE_LLONG, data, totalRows, rowIndex, width);
}

void Hdf5Writer::writeAtTyped(const std::string& name, hid_t type, const void* data, long totalRows,
                              const std::vector<long>& rowIndex, int width) {
  hsize_t dims[2] = {static_cast<hsize_t>(totalRows), static_cast<hsize_t>(width)};
  const int rank = width == 1 ? 1 : 2;
  const hid_t fileSpace = H5Screate_simple(rank, dims, nullptr);
  const hid_t set = H5Dcreate2(id_, name.c_str(), type, fileSpace, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  const std::size_t n = rowIndex.size() * static_cast<std::size_t>(width);
  hsize_t count[1] = {static_cast<hsize_t>(n)};
  const hid_t memSpace = H5Screate_simple(1, count, nullptr);
  if (n > 0) {
    std::vector<hsize_t> coords;
    coords.reserve(n * rank);
    for (long row : rowIndex)
      for (int col = 0; col < width; ++col) {
        coords.push_back(static_cast<hsize_t>(row));
        if (rank == 2) coords.push_back(static_cast<hsize_t>(col));
      }
    H5Sselect_elements(fileSpace, H5S_SELECT_SET, n, coords.data());
  } else {
    H5Sselect_none(fileSpace);
    H5Sselect_none(memSpace);
  }
  writeSelection(name, set, type, memSpace, fileSpace, data);
}

void Hdf5Writer::attribute(const std::string& name, const std::string& value) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.size() + 1);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(id_, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t status = attr < 0 ? -1 : H5Awrite(attr, type, value.c_str());
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
  check(status >= 0, "writing attribute " + name, path_);
}

void Hdf5Writer::attribute(const std::string& name, double value) {
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(id_, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t status = attr < 0 ? -1 : H5Awrite(attr, H5T_NATIVE_DOUBLE, &value);
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  check(status >= 0, "writing attribute " + name, path_);
}

Hdf5Reader::Hdf5Reader(const std::string& path) : path_(path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // a missing file is reported by us, not by HDF5's stack dump
  id_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  check(id_ >= 0, "opening", path);
}

Hdf5Reader::~Hdf5Reader() {
  if (id_ >= 0) H5Fclose(id_);
}

namespace {

template <class T>
std::vector<T> readAll(hid_t file, const std::string& name, hid_t type, const std::string& path) {
  const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  check(set >= 0, "opening dataset " + name, path);
  const hid_t space = H5Dget_space(set);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::vector<T> out(static_cast<std::size_t>(n > 0 ? n : 0));
  const herr_t status = n > 0 ? H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) : 0;
  H5Sclose(space);
  H5Dclose(set);
  check(status >= 0, "reading dataset " + name, path);
  return out;
}

}  // namespace

std::vector<double> Hdf5Reader::doubles(const std::string& name) const {
  return readAll<double>(id_, name, H5T_NATIVE_DOUBLE, path_);
}

std::vector<long long> Hdf5Reader::integers(const std::string& name) const {
  return readAll<long long>(id_, name, H5T_NATIVE_LLONG, path_);
}

bool Hdf5Reader::hasDataset(const std::string& name) const { return H5Lexists(id_, name.c_str(), H5P_DEFAULT) > 0; }

std::string Hdf5Reader::textAttribute(const std::string& name) const {
  const hid_t attr = H5Aopen(id_, name.c_str(), H5P_DEFAULT);
  check(attr >= 0, "opening attribute " + name, path_);
  const hid_t type = H5Aget_type(attr);
  std::string value(H5Tget_size(type), '\0');
  const herr_t status = H5Aread(attr, type, value.data());
  H5Tclose(type);
  H5Aclose(attr);
  check(status >= 0, "reading attribute " + name, path_);
  return value.substr(0, value.find('\0'));
}

double Hdf5Reader::numberAttribute(const std::string& name) const {
  const hid_t attr = H5Aopen(id_, name.c_str(), H5P_DEFAULT);
  check(attr >= 0, "opening attribute " + name, path_);
  double value = 0.0;
  const herr_t status = H5Aread(attr, H5T_NATIVE_DOUBLE, &value);
  H5Aclose(attr);
  check(status >= 0, "reading attribute " + name, path_);
  return value;
}

}  // namespace parcelflow::cfd
