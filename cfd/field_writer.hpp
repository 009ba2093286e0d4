#pragma once
// Writes cell fields with parallel HDF5 plus an XDMF index that ParaView opens (a temporal collection
// of unstructured hexahedral grids). Each rank writes its owned cells as one contiguous hyperslab
// (rank order), so the files hold the fluid cells in "output order"; the dataset `global_id` maps
// output order to global cell ids (background order).
//
// Files in `directory`: <name>_mesh.h5 (/points: 8 corners per cell, /cells: hexahedra, /global_id),
// <name>_NNNNNN.h5 (one dataset per field at the root, /time), and <name>.xdmf (all snapshots).
// Collective: every rank of the mesh communicator calls every method.
#include <string>
#include <utility>
#include <vector>

#include "mesh.hpp"
#include "types.hpp"

namespace parcelflow::cfd {

class FieldWriter {
 public:
  FieldWriter(const Mesh& mesh, std::string directory, std::string name);

  // Adds fields to the next snapshot; the pointers must stay valid until write().
  void addScalar(const std::string& name, const ScalarField& field);
  void addVector(const std::string& name, const VectorField& field);
  // Writes the snapshot at `time`, clears the field list and rewrites the XDMF index.
  void write(double time);

  long globalOffset() const { return offset_; }

 private:
  void writeMesh();
  void writeXdmf() const;
  const Mesh& mesh_;
  std::string directory_, name_;
  long offset_ = 0;  // first output row of this rank
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
