#pragma once
// Builds the local Mesh of every rank (collective over `comm`): selects the fluid cells of the
// Cartesian background with the geometry (with cut cells: merging small ones into a neighbour,
// cell_groups.hpp), partitions them with METIS, adds the ghost layers, the faces, the named boundary
// patches and the halo pattern.
#include <mpi.h>

#include <optional>

#include "cfd/geometry/geometry.hpp"
#include "cfd/mesh/cell_groups.hpp"
#include "cfd/geometry/cut_cell_geometry.hpp"
#include "cfd/mesh/mesh_settings.hpp"
#include "cfd/mesh/mesh.hpp"

namespace parcelflow::cfd {

class MeshBuilder {
 public:
  static Mesh build(const MeshSettings& settings, const Geometry& geometry, MPI_Comm comm);

 private:
  static void addGhostLayers(Mesh& mesh, const CellGroups& groups, int layers);
  static void buildHalo(Mesh& mesh, const std::vector<int>& part);
  // `cut`: the cut-cell geometry with `walls: cut_cells` (open face areas and wall faces), else none.
  static void buildFaces(Mesh& mesh, const Geometry& geometry, const std::optional<CutCellGeometry>& cut,
                         const CellGroups& groups);
  static void addFaceCorrections(Mesh& mesh);
  static void addInternalFace(Mesh& mesh, int low, int high, int d, double area, const Vec3& faceCentre,
                              bool cutCells);
  static void addCutCellWall(Mesh& mesh, const Geometry& geometry, int cell, const CutCellWall& wall,
                             std::vector<long>& localCount);
  // A boundary face of `cell` on the patch named `patch` (counted in localCount).
  static void addBoundaryFace(Mesh& mesh, int cell, const Vec3& area, double magArea, const Vec3& centre,
                              double delta, const std::string& patch, std::vector<long>& localCount);
};

}  // namespace parcelflow::cfd
