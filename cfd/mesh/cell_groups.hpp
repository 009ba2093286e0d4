#pragma once
// The cells of the gas mesh as groups of background cells. Without cut cells every fluid background
// cell is a group of its own. With cut cells a small cut cell (fluid fraction below
// `mesh.small_cell_fraction`, default 1 %) is merged into its face neighbour across its largest open face among the
// neighbours that are not small themselves (the master): the gas cell is their union. Tiny cells
// would otherwise keep fluid centroids a round-off away from their faces (a fraction of 2e-13 put one
// outside its cell, 2e-17 blew the pipe flow up; cfd/README.md, "Cut cells in the solver").
// Masters are never merged, so a merged cell is its master and slivers sharing a face with it, or, for a
// sliver whose open faces all lead to small cells, with another of its slivers (joined in later rounds).
#include <vector>

#include "cfd/geometry/cartesian_background.hpp"
#include "cfd/geometry/cut_cell_geometry.hpp"

namespace parcelflow::cfd {

struct CellGroups {
  std::vector<int> globalOfBackground;     // per background cell: its group's global id, -1 if solid
  std::vector<long> backgroundOfGlobal;    // per group: the master's background index (ids in its order)
  std::vector<std::vector<long>> members;  // per group: its background cells, the master first
  long mergedCells = 0;                    // small cells merged into a master
  long unmergedSmallCells = 0;             // small cells with no open face to a cell that is neither small nor merged
};

// `fluid[b]`: whether background cell b holds fluid; `cut`: the cut-cell geometry or null (staircase).
CellGroups groupCells(const CartesianBackground& bg, const std::vector<bool>& fluid, const CutCellGeometry* cut,
                      double smallFraction);

// The groups' face-connected fluid regions (joined through faces with open area; cells touching only
// along an edge or at a corner are apart): a region that no pressure outlet reaches has no pressure level.
struct FluidRegions {
  std::vector<int> ofGlobal;      // per group: its region, numbered in the order of the groups' ids
  std::vector<long> cells;        // per region: its number of groups
  std::vector<long> firstGlobal;  // per region: its lowest group id
};
FluidRegions fluidRegions(const CartesianBackground& bg, const CellGroups& groups, const CutCellGeometry* cut);

}  // namespace parcelflow::cfd
