// Mesh, geometry, METIS partition and halo: counts, geometry closure, background lookup, ghost
// depth and the halo exchange, on 1, 2 and 3 ranks.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <set>

#include "cfd/mesh/mesh_builder.hpp"
#include "tests/unit/cfd/column_geometry.hpp"

using namespace parcelflow::cfd;

namespace {
MeshSettings columnMesh(int ghostLayers) {
  MeshSettings s;
  s.origin = Vec3(-0.12, -0.12, 0.0);
  s.lengths = Vec3(0.24, 0.24, 0.5);
  s.cells = {12, 12, 25};
  s.ghostLayers = ghostLayers;
  return s;
}

}  // namespace

TEST(Mesh, CountsVolumesAndPatches) {
  const Mesh m = MeshBuilder::build(columnMesh(2), test::columnGeometry(), MPI_COMM_WORLD);
  long owned = m.nOwnedCells();
  long total = 0;
  MPI_Allreduce(&owned, &total, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(total, m.nGlobalCells());
  // Staircase volume close to the exact one (column + tube - baffle).
  const double exact = M_PI * 0.01 * 0.4 + M_PI * 0.0016 * 0.1 - 0.06 * 0.06 * 0.04;
  double volume = 0;
  for (int c = 0; c < m.nOwnedCells(); ++c) volume += m.cellVolume(c);
  volume = m.sum(volume);
  EXPECT_NEAR(volume / exact, 1.0, 0.05);
  for (const char* name : {"zmin", "zmax", "walls", "baffle"}) EXPECT_GE(m.patchId(name), 0) << name;
  EXPECT_EQ(m.patchId("xmin"), -1);  // the column does not touch the box sides
  // Each owned cell is closed: the outward face area vectors sum to zero.
  std::vector<Vec3> closure(m.nOwnedCells(), Vec3::Zero());
  for (int f = 0; f < m.nInternalFaces(); ++f) {
    if (m.faceOwner(f) < m.nOwnedCells()) closure[m.faceOwner(f)] += m.faceArea(f);
    if (m.faceNeighbour(f) < m.nOwnedCells()) closure[m.faceNeighbour(f)] -= m.faceArea(f);
    EXPECT_LT(m.globalId(m.faceOwner(f)), m.globalId(m.faceNeighbour(f)));
  }
  for (int b = 0; b < m.nBoundaryFaces(); ++b) closure[m.boundaryCell(b)] += m.boundaryArea(b);
  for (const auto& v : closure) EXPECT_LT(v.norm(), 1e-15);
}

TEST(Mesh, BackgroundLookupAndGhostDepth) {
  for (int layers : {1, 2, 3}) {
    const Mesh m = MeshBuilder::build(columnMesh(layers), test::columnGeometry(), MPI_COMM_WORLD);
    const auto& bg = m.background();
    EXPECT_DOUBLE_EQ(bg.spacing()[0], 0.02);
    for (int c = 0; c < m.nLocalCells(); ++c) {
      const auto ijk = bg.ijk(m.backgroundIndex(c));
      EXPECT_EQ(m.localCellOfBackground(ijk[0], ijk[1], ijk[2]), c);
      if (c < m.nOwnedCells()) continue;
      // A ghost lies within `layers` (Chebyshev distance) of an owned cell.
      bool nearOwned = false;
      for (int dk = -layers; dk <= layers; ++dk)
        for (int dj = -layers; dj <= layers; ++dj)
          for (int di = -layers; di <= layers; ++di) {
            const int n = m.localCellOfBackground(ijk[0] + di, ijk[1] + dj, ijk[2] + dk);
            nearOwned = nearOwned || (n >= 0 && n < m.nOwnedCells());
          }
      EXPECT_TRUE(nearOwned) << "ghost " << c << " with " << layers << " layers";
    }
    EXPECT_EQ(m.localCellOfBackground(0, 0, 0), -1);   // solid corner
    EXPECT_EQ(m.localCellOfBackground(-1, 5, 5), -1);  // outside the background
    // Every fluid cell within `layers` (Chebyshev distance) of an owned cell is present.
    for (int c = 0; c < m.nOwnedCells(); ++c) {
      const auto ijk = bg.ijk(m.backgroundIndex(c));
      for (int dk = -layers; dk <= layers; ++dk)
        for (int dj = -layers; dj <= layers; ++dj)
          for (int di = -layers; di <= layers; ++di) {
            const int i = ijk[0] + di, j = ijk[1] + dj, k = ijk[2] + dk;
            if (!bg.inside(i, j, k)) continue;
            const Vec3 x = bg.centre(i, j, k);
            if (test::columnGeometry().isFluid(x)) {
              EXPECT_GE(m.localCellOfBackground(i, j, k), 0);
            }
          }
    }
  }
}

TEST(Mesh, HaloExchange) {
  const Mesh m = MeshBuilder::build(columnMesh(2), test::columnGeometry(), MPI_COMM_WORLD);
  ScalarField f(m.nLocalCells(), -1.0);
  VectorField v(m.nLocalCells(), Vec3::Zero());
  for (int c = 0; c < m.nOwnedCells(); ++c) {
    f[c] = static_cast<double>(m.globalId(c));
    v[c] = m.cellCentre(c);
  }
  m.exchange(f);
  m.exchange(v);
  for (int c = 0; c < m.nLocalCells(); ++c) {
    EXPECT_EQ(f[c], static_cast<double>(m.globalId(c)));
    EXPECT_EQ(v[c], m.cellCentre(c));
  }
}

TEST(Mesh, PartitionWeightsShiftTheBalance) {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size == 1) GTEST_SKIP() << "needs more than one rank";
  MeshSettings s = columnMesh(1);
  s.partitionWeights = {{Primitive::box(Vec3(-1, -1, 0), Vec3(1, 1, 0.2)), 10}};
  const Mesh m = MeshBuilder::build(s, test::columnGeometry(), MPI_COMM_WORLD);
  double weight = 0;
  for (int c = 0; c < m.nOwnedCells(); ++c) weight += m.cellCentre(c)[2] < 0.2 ? 10 : 1;
  const double total = m.sum(weight), most = m.max(weight);
  EXPECT_LT(most / (total / size), 1.1);  // balanced in weight, not in cells
}
