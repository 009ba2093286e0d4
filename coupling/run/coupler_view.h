// The coupler's view of a gas mesh: the background grid the parcels are binned on, and every owned gas cell's
// background cells (a cut cell's master and merged slivers) with their fluid shares, for the CellOwnerMap.
#pragma once

#include <vector>

#include "coupling/exchange/cell_owner_map.h"
#include "cfd/mesh/mesh.hpp"
#include "coupling/run/parcel_mesh_coupler.h"

namespace parcelflow::coupling {

inline BackgroundGrid backgroundGridOf(const cfd::Mesh& mesh) {
  BackgroundGrid grid;
  for (int d = 0; d < 3; ++d) {
    grid.origin[d] = mesh.background().origin()[d];
    grid.spacing[d] = mesh.background().spacing()[d];
    grid.cells[d] = mesh.background().n()[d];
  }
  return grid;
}

inline std::vector<OwnedPiece> ownedPiecesOf(const cfd::Mesh& mesh) {
  std::vector<OwnedPiece> pieces;
  for (int c = 0; c < mesh.nOwnedCells(); ++c)
    for (int m = 0; m < mesh.nMembers(c); ++m) pieces.push_back({mesh.member(c, m), c, mesh.memberFluidFraction(c, m)});
  return pieces;
}

}  // namespace parcelflow::coupling
