// The mesh builder with `walls: cut_cells` (issue 31, part 2): fluid volumes, open faces and wall faces
// from the cut-cell geometry, small cut cells merged into a neighbour, partitioned and closed on 1, 2
// and 3 ranks.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>

#include "cfd/mesh/cell_groups.hpp"
#include "cfd/mesh/mesh_builder.hpp"
#include "tests/unit/cfd/column_geometry.hpp"
#include "cfd/geometry/surface_from_geometry.hpp"

using namespace parcelflow::cfd;

namespace {
MeshSettings cutColumnMesh() {
  MeshSettings s;
  s.origin = Vec3(-0.12, -0.12, 0.0);
  s.lengths = Vec3(0.24, 0.24, 0.5);
  s.cells = {12, 12, 25};
  s.walls = WallRepresentation::CutCells;
  return s;
}

}  // namespace

TEST(CutCellMesh, VolumesClosureAndPatches) {
  const MeshSettings settings = cutColumnMesh();
  const Geometry geometry = test::columnGeometry();
  const Mesh m = MeshBuilder::build(settings, geometry, MPI_COMM_WORLD);
  long owned = m.nOwnedCells(), total = 0;
  MPI_Allreduce(&owned, &total, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(total, m.nGlobalCells());

  // The fluid volumes add up to the volume of the tessellated surface the geometry cut the cells with.
  const double surfaceVolume = surfaceOfGeometry(geometry, m.background()).volume();
  double volume = 0;
  for (int c = 0; c < m.nOwnedCells(); ++c) volume += m.cellVolume(c);
  volume = m.sum(volume);
  const double cellVolume = m.background().cellVolume();
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf("[measured] cut-cell column: fluid volume %.12e, surface volume %.12e, relative %.2e\n", volume,
                surfaceVolume, volume / surfaceVolume - 1.0);
  EXPECT_NEAR(volume / surfaceVolume, 1.0, 1e-10);

  for (const char* name : {"zmin", "zmax", "walls", "baffle"}) EXPECT_GE(m.patchId(name), 0) << name;

  // Each owned cell is closed by its open faces and its wall face: the area vectors sum to zero.
  const double faceArea = std::pow(cellVolume, 2.0 / 3.0);
  std::vector<Vec3> closure(m.nOwnedCells(), Vec3::Zero());
  for (int f = 0; f < m.nInternalFaces(); ++f) {
    EXPECT_GT(m.faceMagArea(f), 0.0);
    if (m.faceOwner(f) < m.nOwnedCells()) closure[m.faceOwner(f)] += m.faceArea(f);
    if (m.faceNeighbour(f) < m.nOwnedCells()) closure[m.faceNeighbour(f)] -= m.faceArea(f);
  }
  for (int b = 0; b < m.nBoundaryFaces(); ++b) {
    closure[m.boundaryCell(b)] += m.boundaryArea(b);
    EXPECT_GT(m.boundaryDelta(b), 0.0);
  }
  double worst = 0;
  for (const auto& v : closure) worst = std::max(worst, v.norm() / faceArea);
  if (rank == 0) std::printf("[measured] cut-cell column: worst closure on rank 0 %.2e of a face area\n", worst);
  EXPECT_LT(worst, 1e-9);

  // The wall area on the walls and baffle patches: the side of the column and tube, the annulus at
  // z = 0.4 and the baffle's 5 faces (z = 0 and 0.5 are the zmin/zmax sides).
  double wall = 0;
  for (int b = 0; b < m.nBoundaryFaces(); ++b)
    if (m.boundaryPatch(b) == m.patchId("walls") || m.boundaryPatch(b) == m.patchId("baffle"))
      wall += m.boundaryMagArea(b);
  wall = m.sum(wall);
  const double side = 2 * 128 * std::sin(M_PI / 128);  // perimeter / r of the 128-gon
  const double polygon = 0.5 * 128 * std::sin(2 * M_PI / 128);  // area / r^2
  const double expected = side * 0.1 * 0.4 + side * 0.04 * 0.1 + polygon * (0.01 - 0.0016) +
                          4 * 0.06 * 0.04 + 0.06 * 0.06 * 2;
  if (rank == 0)
    std::printf("[measured] cut-cell column: wall area %.6e m2, 128-gon expected %.6e m2\n", wall, expected);
  // The wall face of a cell is |sum of area vectors|: less than the true area only where one cell holds
  // wall pieces facing different ways (the baffle's edges, the annulus meeting the tube).
  EXPECT_LE(wall, expected * (1 + 1e-9));
  EXPECT_GT(wall, 0.97 * expected);
}

// The faces' axis and non-orthogonality n - d / (d.n), d between the centres, that the gas solver reads
// instead of recomputing them: every face has one, and it is listed as non-orthogonal exactly when it is not
// zero, which happens only between cut cells' centroids (a staircase of the same geometry has none).
TEST(CutCellMesh, NonOrthogonalFacesAreThoseBetweenOffsetCentroids) {
  for (const WallRepresentation walls : {WallRepresentation::CutCells, WallRepresentation::Staircase}) {
    MeshSettings settings = cutColumnMesh();
    settings.walls = walls;
    const Mesh m = MeshBuilder::build(settings, test::columnGeometry(), MPI_COMM_WORLD);
    std::vector<int> expected;
    std::vector<Vec3> expectedOffsets;
    for (int f = 0; f < m.nInternalFaces(); ++f) {
      const Vec3 n = m.faceArea(f) / m.faceMagArea(f);
      const Vec3 d = m.cellCentre(m.faceNeighbour(f)) - m.cellCentre(m.faceOwner(f));
      const Vec3 offset = n - d / d.dot(n);
      EXPECT_EQ(m.faceAxis(f), dominantAxis(m.faceArea(f)));
      EXPECT_DOUBLE_EQ(std::abs(m.faceArea(f)[m.faceAxis(f)]), m.faceMagArea(f));  // axis-aligned
      if (offset.isZero(0.0)) continue;
      expected.push_back(f);
      expectedOffsets.push_back(offset);
    }
    ASSERT_EQ(m.nonOrthogonalFaces(), expected);  // then each listed face has its vector
    for (std::size_t listed = 0; listed < expected.size(); ++listed)
      EXPECT_EQ(m.nonOrthogonality(listed), expectedOffsets[listed]);
    long listed = static_cast<long>(expected.size());
    MPI_Allreduce(MPI_IN_PLACE, &listed, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
    if (walls == WallRepresentation::Staircase) EXPECT_EQ(listed, 0);
    else EXPECT_GT(listed, 0);
  }
}

namespace {
// The pipe of the next two tests on 24 x 24 x 1 cut cells, small ones merged below `smallFraction`.
MeshSettings sliverPipeMesh(double smallFraction) {
  MeshSettings settings;
  settings.origin = Vec3(-0.6, -0.6, 0.0);
  settings.lengths = Vec3(1.2, 1.2, 0.1);
  settings.cells = {24, 24, 1};
  settings.walls = WallRepresentation::CutCells;
  settings.smallCellFraction = smallFraction;
  return settings;
}
const Geometry sliverPipe({{Geometry::Op::Union, Primitive::cylinder(0, 0, 0.5 + 5e-11, 0, 0.1), ""}});
}  // namespace

// A pipe of radius 0.5 m + 5e-11 m on 24 x 24 cells of 0.05 m: the 128-gon's corner at (R, 0) passes
// the grid line x = 0.5 by 5e-11 m and leaves slivers of 2e-17 of a cell beyond it. Every cut cell
// under 1 % is merged into a neighbour (cell_groups.hpp): no cell is smaller, the volume is kept, the
// merged cells close, every face has a positive delta, and the sliver's background cell gives its cell.
TEST(CutCellMesh, SmallCellsMergedIntoANeighbour) {
  const Geometry& geometry = sliverPipe;
  const Mesh m = MeshBuilder::build(sliverPipeMesh(kDefaultSmallCellFraction), geometry, MPI_COMM_WORLD);
  const double cellVolume = m.background().cellVolume();
  EXPECT_EQ(m.mergedCells(), 12);  // 4 below 1 % at R = 0.5 m, and the slivers on the 4 axes
  EXPECT_EQ(m.unmergedSmallCells(), 0);

  double volume = 0, smallest = 1;
  for (int c = 0; c < m.nOwnedCells(); ++c) {
    volume += m.cellVolume(c);
    smallest = std::min(smallest, m.cellVolume(c) / cellVolume);
  }
  EXPECT_GE(-m.max(-smallest), kDefaultSmallCellFraction);
  const double surfaceVolume = surfaceOfGeometry(geometry, m.background()).volume();
  EXPECT_NEAR(m.sum(volume) / surfaceVolume, 1.0, 1e-10);

  std::vector<Vec3> closure(m.nOwnedCells(), Vec3::Zero());
  for (int f = 0; f < m.nInternalFaces(); ++f) {
    EXPECT_GT(m.faceDelta(f), 0.0);
    EXPECT_GT(m.globalId(m.faceNeighbour(f)), m.globalId(m.faceOwner(f)));
    if (m.faceOwner(f) < m.nOwnedCells()) closure[m.faceOwner(f)] += m.faceArea(f);
    if (m.faceNeighbour(f) < m.nOwnedCells()) closure[m.faceNeighbour(f)] -= m.faceArea(f);
  }
  for (int b = 0; b < m.nBoundaryFaces(); ++b) {
    EXPECT_GT(m.boundaryDelta(b), 0.0);
    closure[m.boundaryCell(b)] += m.boundaryArea(b);
  }
  double worst = 0;
  for (const auto& v : closure) worst = std::max(worst, v.norm() / (0.05 * 0.1));
  EXPECT_LT(m.max(worst), 1e-9);

  // The sliver beyond x = 0.5 at y just above 0 (background cell (22, 12)) is part of the cell of its
  // master (21, 12) on whichever rank holds that cell.
  const int sliver = m.localCellOfBackground(22, 12, 0), master = m.localCellOfBackground(21, 12, 0);
  EXPECT_EQ(sliver, master);
  if (master >= 0) {
    EXPECT_EQ(m.backgroundIndex(master), m.background().index(21, 12, 0));
  }
}

// mesh.small_cell_fraction: the same pipe with cut cells under 5 % merged: more cells merged, none
// smaller, the volume kept.
TEST(CutCellMesh, SmallCellFractionSetsTheMergeThreshold) {
  const Geometry& geometry = sliverPipe;
  const Mesh m = MeshBuilder::build(sliverPipeMesh(0.05), geometry, MPI_COMM_WORLD);
  EXPECT_GT(m.mergedCells(), 12);  // 12 at the default 1 %
  EXPECT_EQ(m.unmergedSmallCells(), 0);
  double volume = 0, smallest = 1;
  for (int c = 0; c < m.nOwnedCells(); ++c) {
    volume += m.cellVolume(c);
    smallest = std::min(smallest, m.cellVolume(c) / m.background().cellVolume());
  }
  EXPECT_GE(-m.max(-smallest), 0.05);
  EXPECT_NEAR(m.sum(volume) / surfaceOfGeometry(geometry, m.background()).volume(), 1.0, 1e-10);
}

// The top of the FCC column (cases/psri_fcc_bubbling_bed, full case): z = 7.0 lies 2e-8 m above the face
// 156 dz of lengths 7.4935897 / 167 cells, so the cells above it hold slivers of the column; in the column's
// four corners those slivers (9e-9 of a cell) have only small cut cells as open neighbours. They join their
// neighbour's merged cell in a second round: none is left alone, none is under 1 %, the volume is kept.
TEST(CutCellMesh, SliversAmongSmallCellsJoinAMergedNeighbour) {
  const double top = 7.4935897, dz = top / 167;
  MeshSettings settings;
  settings.origin = Vec3(-0.45, -0.45, 152 * dz);
  settings.lengths = Vec3(0.9, 0.9, 8 * dz);
  settings.cells = {20, 20, 8};
  settings.walls = WallRepresentation::CutCells;
  const Geometry geometry({{Geometry::Op::Union, Primitive::cylinder(0, 0, 0.45, 0.0, 7.0), ""},
                           {Geometry::Op::Union, Primitive::cylinder(0, 0, 0.1, 7.0, top), ""}});
  const Mesh m = MeshBuilder::build(settings, geometry, MPI_COMM_WORLD);
  EXPECT_EQ(m.unmergedSmallCells(), 0);  // 4 when merging went one level deep
  EXPECT_GT(m.mergedCells(), 0);
  double volume = 0, smallest = 1;
  for (int c = 0; c < m.nOwnedCells(); ++c) {
    volume += m.cellVolume(c);
    smallest = std::min(smallest, m.cellVolume(c) / m.background().cellVolume());
  }
  EXPECT_GE(-m.max(-smallest), kDefaultSmallCellFraction);
  // the 128-gons' prisms within the box: the column up to 7.0, the tube above
  const double polygon = 0.5 * defaultCircleSegments * std::sin(2 * M_PI / defaultCircleSegments);
  const double expected = polygon * (0.45 * 0.45 * (7.0 - 152 * dz) + 0.1 * 0.1 * (160 * dz - 7.0));
  EXPECT_NEAR(m.sum(volume) / expected, 1.0, 1e-10);
  for (int b = 0; b < m.nBoundaryFaces(); ++b) EXPECT_GT(m.boundaryDelta(b), 0.0);
}
