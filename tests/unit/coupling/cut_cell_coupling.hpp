#pragma once
// The coupler's view of a gas mesh, as coupled_run.cpp builds it: the background grid and every owned gas
// cell's background cells (master and merged slivers) with their fluid shares.
#include <vector>

#include "cfd/mesh.hpp"
#include "parcel_mesh_coupler.h"

namespace parcelflow::coupling::test {

inline BackgroundGrid gridOf(const cfd::Mesh& mesh) {
  BackgroundGrid grid;
  for (int d = 0; d < 3; ++d) {
    grid.origin[d] = mesh.background().origin()[d];
    grid.spacing[d] = mesh.background().spacing()[d];
    grid.cells[d] = mesh.background().n()[d];
  }
  return grid;
}

inline std::vector<OwnedPiece> piecesOf(const cfd::Mesh& mesh) {
  std::vector<OwnedPiece> pieces;
  for (int c = 0; c < mesh.nOwnedCells(); ++c)
    for (int m = 0; m < mesh.nMembers(c); ++m) pieces.push_back({mesh.member(c, m), c, mesh.memberFluidFraction(c, m)});
  return pieces;
}

}  // namespace parcelflow::coupling::test
