#pragma once
// What the mesh is built from: the Cartesian background, the ghost layers, METIS weights and how the walls of
// the geometry are represented. The gas settings hold one (solver/gas_settings.hpp).
#include <array>
#include <vector>

#include "cfd/base/types.hpp"
#include "cfd/geometry/primitive.hpp"

namespace parcelflow::cfd {

struct PartitionWeight {
  Primitive region;
  int weight = 1;  // METIS vertex weight of cells whose centre is inside `region`
};

// How the gas sees the walls of `geometry:`: whole background cells selected by their centre, or cut
// cells (fluid volume, open face areas and a wall face per cut cell; cfd/README.md, "Cut cells in the
// solver").
enum class WallRepresentation { Staircase, CutCells };

// MFiX removes cut cells under 1 % of the volume; here they are merged into a neighbour (cell_groups.hpp),
// so no volume is lost. case.yaml: mesh.small_cell_fraction.
constexpr double kDefaultSmallCellFraction = 0.01;

struct MeshSettings {
  Vec3 origin = Vec3::Zero();
  Vec3 lengths = Vec3::Ones();
  std::array<int, 3> cells{1, 1, 1};
  int ghostLayers = 2;
  std::vector<PartitionWeight> partitionWeights;  // later entries override earlier ones
  WallRepresentation walls = WallRepresentation::Staircase;
  double smallCellFraction = kDefaultSmallCellFraction;  // cut cells below this share of a cell are merged
};

}  // namespace parcelflow::cfd
