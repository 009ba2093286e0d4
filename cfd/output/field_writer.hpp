#pragma once
// Writes cell fields with parallel HDF5 plus an XDMF index that ParaView opens (a temporal collection
// of unstructured hexahedral grids). Row r of every dataset is the fluid cell of global id r (background
// order), whatever the number of ranks, so a run continued on other ranks extends the same series;
// `global_id` holds r.
//
// Files in `directory`: <name>_mesh.h5 (/points: 8 corners per cell, /cells: hexahedra (a cell's
// background box), /global_id, /fluid_fraction: fluid volume over the boxes' volume, in every snapshot),
// <name>_NNNNNN.h5 (one dataset per field at the root, /time), and <name>.xdmf (all snapshots).
// Collective: every rank of the mesh communicator calls every method.
#include <string>
#include <utility>
#include <vector>

#include "cfd/mesh/mesh.hpp"
#include "cfd/base/types.hpp"

namespace parcelflow::cfd {

class FieldWriter {
 public:
  static constexpr const char* kFluidFraction = "fluid_fraction";
  FieldWriter(const Mesh& mesh, std::string directory, std::string name);

  // Adds fields to the next snapshot; the pointers must stay valid until write().
  void addScalar(const std::string& name, const ScalarField& field);
  void addVector(const std::string& name, const VectorField& field);
  // Writes the snapshot at `time`, clears the field list and rewrites the XDMF index.
  void write(double time);
  // A restarted run: the series already holds snapshots at `times` (files <name>_000000.h5 on) with these
  // fields; the next write() is number times.size(). Call before the first write.
  void continueSeries(const std::vector<double>& times, const std::vector<std::string>& scalars,
                      const std::vector<std::string>& vectors);
  std::size_t snapshots() const { return snapshots_.size(); }
  std::vector<double> snapshotTimes() const {
    std::vector<double> t;
    for (const auto& s : snapshots_) t.push_back(s.time);
    return t;
  }

 private:
  void writeMesh();
  void writeXdmf() const;
  std::string snapshotFile(std::size_t index) const;
  const Mesh& mesh_;
  std::string directory_, name_;
  std::vector<long> row_, pointRow_;  // output rows of the owned cells and of their 8 corners
  std::vector<std::pair<std::string, const ScalarField*>> scalars_;
  std::vector<std::pair<std::string, const VectorField*>> vectors_;
  struct Snapshot {
    double time;
    std::string file;
    std::vector<std::string> scalars, vectors;
  };
  std::vector<Snapshot> snapshots_;
};

}  // namespace parcelflow::cfd
