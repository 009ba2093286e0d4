#include "cfd/output/field_writer.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "cfd/io/hdf5_file.hpp"
#include "cfd/base/internal_error.hpp"

namespace parcelflow::cfd {

FieldWriter::FieldWriter(const Mesh& mesh, std::string directory, std::string name)
    : mesh_(mesh), directory_(std::move(directory)), name_(std::move(name)) {
  for (int c = 0; c < mesh_.nOwnedCells(); ++c) {
    row_.push_back(mesh_.globalId(c));
    for (int k = 0; k < 8; ++k) pointRow_.push_back(8 * mesh_.globalId(c) + k);
  }
  writeMesh();
}

void FieldWriter::continueSeries(const std::vector<double>& times, const std::vector<std::string>& scalars,
                                 const std::vector<std::string>& vectors) {
  PARCELFLOW_ASSERT(snapshots_.empty(), "continueSeries before the first write");
  for (double t : times) snapshots_.push_back({t, snapshotFile(snapshots_.size()), scalars, vectors});
}

std::string FieldWriter::snapshotFile(std::size_t index) const { return seriesFileName(name_, index); }

void FieldWriter::writeMesh() {
  const int n = mesh_.nOwnedCells();
  const CartesianBackground& bg = mesh_.background();
  const Vec3 h = bg.spacing();
  // A cell is drawn as its background box (a merged cut cell as its master's), whose corners are exact
  // grid points; a cut cell's centre is its fluid centroid, not the box's.
  // Corners in VTK hexahedron order.
  static const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                   {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  std::vector<double> points(static_cast<std::size_t>(n) * 24);
  std::vector<long long> cells(static_cast<std::size_t>(n) * 8), ids(n);
  for (int c = 0; c < n; ++c) {
    const auto ijk = bg.ijk(mesh_.backgroundIndex(c));
    for (int k = 0; k < 8; ++k) {
      for (int d = 0; d < 3; ++d) points[(8 * c + k) * 3 + d] = bg.origin()[d] + (ijk[d] + corner[k][d]) * h[d];
      cells[8 * c + k] = 8 * mesh_.globalId(c) + k;
    }
    ids[c] = mesh_.globalId(c);
  }
  // The fluid fraction of the background boxes a cell spans (a merged cell spans its members'), so that
  // ParaView shows cut walls: 1 in whole cells.
  std::vector<int> boxes(n, 0);
  for (int k = 0; k < bg.n()[2]; ++k)
    for (int j = 0; j < bg.n()[1]; ++j)
      for (int i = 0; i < bg.n()[0]; ++i) {
        const int c = mesh_.localCellOfBackground(i, j, k);
        if (c >= 0 && c < n) ++boxes[c];
      }
  std::vector<double> fluidFraction(n);
  for (int c = 0; c < n; ++c) fluidFraction[c] = mesh_.cellVolume(c) / (boxes[c] * h.prod());
  const long total = mesh_.nGlobalCells();
  Hdf5Writer file(directory_ + "/" + name_ + "_mesh.h5", mesh_.comm());
  file.writeAt("points", points.data(), 8 * total, pointRow_, 3);
  file.writeAt("cells", cells.data(), total, row_, 8);
  file.writeAt("global_id", ids.data(), total, row_, 1);
  file.writeAt(kFluidFraction, fluidFraction.data(), total, row_, 1);
  file.close();
}

void FieldWriter::addScalar(const std::string& name, const ScalarField& field) {
  scalars_.emplace_back(name, &field);
}

void FieldWriter::addVector(const std::string& name, const VectorField& field) {
  vectors_.emplace_back(name, &field);
}

void FieldWriter::write(double time) {
  const std::string file_name = snapshotFile(snapshots_.size());
  const int n = mesh_.nOwnedCells();
  const long total = mesh_.nGlobalCells();
  Snapshot snap{time, file_name, {}, {}};
  {
    Hdf5Writer file(directory_ + "/" + file_name, mesh_.comm());
    const double t[1] = {time};
    file.write("time", t, 1, 0, mesh_.rank() == 0 ? 1 : 0, 1);
    for (const auto& [name, field] : scalars_) {
      PARCELFLOW_ASSERT(static_cast<int>(field->size()) >= n, "short field " + name);
      file.writeAt(name, field->data(), total, row_, 1);
      snap.scalars.push_back(name);
    }
    for (const auto& [name, field] : vectors_) {
      PARCELFLOW_ASSERT(static_cast<int>(field->size()) >= n, "short field " + name);
      file.writeAt(name, (*field)[0].data(), total, row_, 3);
      snap.vectors.push_back(name);
    }
    file.close();
  }
  scalars_.clear();
  vectors_.clear();
  snapshots_.push_back(snap);
  if (mesh_.rank() == 0) writeXdmf();
}

void FieldWriter::writeXdmf() const {
  const long n = mesh_.nGlobalCells();
  const std::string meshFile = name_ + "_mesh.h5";
  // Written beside and renamed over the old index: an interrupted run keeps a complete XDMF that lists
  // only snapshots whose files were closed.
  const std::string path = directory_ + "/" + name_ + ".xdmf", partial = path + ".partial";
  std::ofstream x(partial);
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
    x << "    <Attribute Name=\"" << kFluidFraction << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n";
    item(std::to_string(n), "Float", meshFile + ":/" + kFluidFraction);
    x << "    </Attribute>\n";
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
  x.close();
  if (!x || std::rename(partial.c_str(), path.c_str()) != 0)
    throw std::runtime_error("cannot write the field index " + path);
}

}  // namespace parcelflow::cfd
