#pragma once
// The local part of the face-based gas mesh on one rank: owned cells first, then ghosts.
//
// Ghosts are the fluid cells within `ghost_layers` background cells (Chebyshev distance) of an owned
// cell; exchange(field) copies their owners' values into them. The solver's stencils are the faces of
// owned cells, so it reads only the ghosts sharing a face with an owned cell (their values and their
// gradients, exchanged from the owners); one layer is enough for it.
// The coupling layer reads owned cells only: it sends particle contributions to the ranks owning the
// cells (coupling/exchange), so ghosts need not cover a deposition kernel.
// Geometry is stored per cell and per face (volumes, centres, area vectors), so cut cells can later
// replace the staircase cells without changing the solver.
#include <mpi.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "cfd/geometry/cartesian_background.hpp"
#include "cfd/mesh/halo.hpp"
#include "cfd/base/types.hpp"

namespace parcelflow::cfd {

class Mesh {
 public:
  // A duplicate of the communicator given to MeshBuilder: the gas solver's halo messages and
  // reductions never mix with the caller's.
  MPI_Comm comm() const { return comm_; }
  int rank() const { return rank_; }
  int nRanks() const { return nRanks_; }

  const CartesianBackground& background() const { return background_; }
  // Local index of the fluid cell (owned or ghost) at background index (i, j, k); -1 if it is solid,
  // outside the background or not present on this rank. A small cut cell merged into a neighbour
  // (cell_groups.hpp) gives the merged cell.
  int localCellOfBackground(int i, int j, int k) const {
    return background_.inside(i, j, k) ? backgroundToLocal_[background_.index(i, j, k)] : -1;
  }

  int nOwnedCells() const { return nOwned_; }
  int nLocalCells() const { return static_cast<int>(globalId_.size()); }
  long nGlobalCells() const { return nGlobal_; }
  // Small cut cells merged into a neighbour, and those left alone (no open face to a cell that is not
  // small), over the whole mesh.
  long mergedCells() const { return mergedCells_; }
  long unmergedSmallCells() const { return unmergedSmallCells_; }
  // Global fluid-cell id (ordered like the background's linear index of the cell or its master), the
  // same on every rank count.
  long globalId(int cell) const { return globalId_[cell]; }
  // Face-connected fluid regions (cell_groups.hpp): the region of a local cell, their number, and per
  // region its cell count and the centre of its lowest-id cell's background box (for messages).
  int fluidRegion(int cell) const { return fluidRegion_[cell]; }
  int nFluidRegions() const { return static_cast<int>(fluidRegionCells_.size()); }
  long fluidRegionCells(int region) const { return fluidRegionCells_[region]; }
  const Vec3& fluidRegionPoint(int region) const { return fluidRegionPoint_[region]; }
  // The background cell of a cell (of a merged cell: its master's).
  long backgroundIndex(int cell) const { return backgroundIndex_[cell]; }
  // The background cells a cell is made of (one; several where small cut cells were merged into it, the
  // master first) and the fluid share of each (1 off the walls and on a staircase).
  int nMembers(int cell) const { return memberStart_[cell + 1] - memberStart_[cell]; }
  long member(int cell, int m) const { return memberBackground_[memberStart_[cell] + m]; }
  double memberFluidFraction(int cell, int m) const { return memberFraction_[memberStart_[cell] + m]; }
  const Vec3& cellCentre(int cell) const { return cellCentre_[cell]; }
  double cellVolume(int cell) const { return cellVolume_[cell]; }

  // Internal faces: every face with at least one owned cell. owner < neighbour in global id; the area
  // vector points from owner to neighbour; weight = interpolation weight of the owner value.
  int nInternalFaces() const { return static_cast<int>(faceOwner_.size()); }
  int faceOwner(int f) const { return faceOwner_[f]; }
  int faceNeighbour(int f) const { return faceNeighbour_[f]; }
  const Vec3& faceArea(int f) const { return faceArea_[f]; }
  double faceMagArea(int f) const { return faceMagArea_[f]; }
  const Vec3& faceCentre(int f) const { return faceCentre_[f]; }
  double faceWeight(int f) const { return faceWeight_[f]; }
  double faceDelta(int f) const { return faceDelta_[f]; }  // owner-to-neighbour centre distance
  int faceAxis(int f) const { return faceAxis_[f]; }  // the axis of the face's normal (faces are axis-aligned)
  // The faces where n - d / (d.n), d = x_N - x_O, is not zero (between cut cells' centroids; none between
  // whole cells), ascending, and that vector of the listed face `listed`: what the derivative along d lacks
  // of the normal derivative, per unit gradient and face (the non-orthogonal correction). Kept for the
  // listed faces only, so that a mesh of whole cells pays no memory for it.
  const std::vector<int>& nonOrthogonalFaces() const { return nonOrthogonalFaces_; }
  const Vec3& nonOrthogonality(std::size_t listed) const { return nonOrthogonality_[listed]; }

  // Boundary faces of owned cells; area vector points out of the domain.
  int nBoundaryFaces() const { return static_cast<int>(boundaryCell_.size()); }
  int boundaryCell(int b) const { return boundaryCell_[b]; }
  const Vec3& boundaryArea(int b) const { return boundaryArea_[b]; }
  double boundaryMagArea(int b) const { return boundaryMagArea_[b]; }
  const Vec3& boundaryCentre(int b) const { return boundaryCentre_[b]; }
  double boundaryDelta(int b) const { return boundaryDelta_[b]; }  // cell centre to face centre
  int boundaryPatch(int b) const { return boundaryPatch_[b]; }

  // Patches are global: the same names and ids on every rank; a patch may have no face on a rank.
  const std::vector<std::string>& patchNames() const { return patchNames_; }
  int patchId(const std::string& name) const;  // -1 when no face of the whole mesh has that name
  long patchGlobalFaces(int patch) const { return patchGlobalFaces_[patch]; }

  void exchange(ScalarField& field) const { halo_.exchange(field); }
  void exchange(VectorField& field) const { halo_.exchange(field); }

  // Global sums over owned cells.
  double sumOwned(const ScalarField& field) const;
  double sum(double localValue) const;
  double max(double localValue) const;

 private:
  friend class MeshBuilder;
  MPI_Comm comm_ = MPI_COMM_NULL;
  std::shared_ptr<MPI_Comm> commOwner_;  // frees the duplicate with the last copy of the mesh
  int rank_ = 0, nRanks_ = 1;
  CartesianBackground background_;
  std::vector<int> backgroundToLocal_;
  int nOwned_ = 0;
  long nGlobal_ = 0, mergedCells_ = 0, unmergedSmallCells_ = 0;
  std::vector<long> globalId_, backgroundIndex_;
  std::vector<int> memberStart_{0};
  std::vector<long> memberBackground_;
  std::vector<double> memberFraction_;
  std::vector<int> fluidRegion_;
  std::vector<long> fluidRegionCells_;
  std::vector<Vec3> fluidRegionPoint_;
  std::vector<Vec3> cellCentre_;
  std::vector<double> cellVolume_;
  std::vector<int> faceOwner_, faceNeighbour_;
  std::vector<Vec3> faceArea_, faceCentre_;
  std::vector<double> faceMagArea_, faceWeight_, faceDelta_;
  std::vector<std::int8_t> faceAxis_;
  std::vector<int> nonOrthogonalFaces_;
  std::vector<Vec3> nonOrthogonality_;
  std::vector<int> boundaryCell_, boundaryPatch_;
  std::vector<Vec3> boundaryArea_, boundaryCentre_;
  std::vector<double> boundaryMagArea_, boundaryDelta_;
  std::vector<std::string> patchNames_;
  std::vector<long> patchGlobalFaces_;
  Halo halo_;
};

}  // namespace parcelflow::cfd
