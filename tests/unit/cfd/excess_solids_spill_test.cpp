// spillExcessSolids: the solids volume kept to round-off, no cell left above the bound when there is room,
// a field within the bound untouched, and the same field on 1, 2 and 3 ranks.
#include <gtest/gtest.h>
#include <mpi.h>

#include <array>
#include <cmath>
#include <vector>

#include "cfd/fv/excess_solids_spill.hpp"
#include "cfd/mesh/mesh_builder.hpp"
#include "tests/unit/cfd/same_on_rank_zero_alone.hpp"

using namespace parcelflow::cfd;

namespace {
Mesh mesh(MPI_Comm comm) {
  MeshSettings s;
  s.lengths = Vec3(0.0375, 0.0375, 0.05);
  s.cells = {12, 12, 16};
  return MeshBuilder::build(s, Geometry(), comm);
}

// Lumps of a packed bed of parcels larger than the cells: 0.66 on average, every third cell 0.85 in the
// bottom half, the cells between them lower; empty above.
double lumpy(const Mesh& m, int c) {
  const Vec3& x = m.cellCentre(c);
  const Vec3& h = m.background().spacing();
  if (x[2] > 0.025) return 0.0;
  const int i = static_cast<int>(x[0] / h[0]) + 2 * static_cast<int>(x[1] / h[1]) + static_cast<int>(x[2] / h[2]);
  return i % 3 == 0 ? 0.85 : 0.585;
}

std::vector<double> field(const Mesh& m) {
  std::vector<double> s(m.nOwnedCells());
  for (int c = 0; c < m.nOwnedCells(); ++c) s[c] = lumpy(m, c);
  return s;
}
}  // namespace

TEST(ExcessSolidsSpill, KeepsTheVolumeAndLeavesNoCellAboveTheBound) {
  const Mesh m = mesh(MPI_COMM_WORLD);
  std::vector<double> s = field(m);
  double before = 0.0, above = 0.0;
  for (int c = 0; c < m.nOwnedCells(); ++c) {
    before += m.cellVolume(c) * s[c];
    above += s[c] > 0.7 ? 1.0 : 0.0;
  }
  before = m.sum(before);
  ASSERT_GT(m.sum(above), 100.0);  // the lumps are there
  const SpillStats stats = spillExcessSolids(m, s, 0.7);
  double after = 0.0, highest = 0.0;
  for (int c = 0; c < m.nOwnedCells(); ++c) {
    after += m.cellVolume(c) * s[c];
    highest = std::max(highest, s[c]);
    EXPECT_GE(s[c], 0.0);
  }
  EXPECT_NEAR(m.sum(after), before, 1e-13 * before);
  MPI_Allreduce(MPI_IN_PLACE, &highest, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_LE(highest, 0.7 * (1 + 1e-12));
  EXPECT_GT(stats.passes, 0);
  EXPECT_LT(stats.passes, 20);
}

TEST(ExcessSolidsSpill, LeavesAFieldWithinTheBoundUntouched) {
  const Mesh m = mesh(MPI_COMM_WORLD);
  std::vector<double> s = field(m), t = s;
  const SpillStats stats = spillExcessSolids(m, s, 0.9);
  EXPECT_EQ(stats.passes, 0);
  EXPECT_EQ(stats.cells, 0);
  EXPECT_EQ(s, t);
}

TEST(ExcessSolidsSpill, GivesTheSameFieldOnAnyNumberOfRanks) {
  const Mesh m = mesh(MPI_COMM_WORLD);
  std::vector<double> s = field(m);
  spillExcessSolids(m, s, 0.7);
  const std::vector<double> global = test::byGlobalId(m, s);
  test::onRankZeroAlone([&](MPI_Comm self) {
    const Mesh alone = mesh(self);
    std::vector<double> t = field(alone);
    spillExcessSolids(alone, t, 0.7);
    for (int c = 0; c < alone.nOwnedCells(); ++c) EXPECT_NEAR(global[alone.globalId(c)], t[c], 1e-14);
  });
}
