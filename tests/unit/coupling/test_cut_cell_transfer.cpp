// Parcels on cut cells (issue 31, part 3): a pipe of radius 0.5 m on 24 x 24 x 2 cells of 0.05 m, whose
// polygon passes the grid lines x, y = +-0.5 by 5e-11 m (the mesh tests' pipe): cut cells, and slivers and
// cells under 1 % merged into a neighbour. Deposits land in fluid volume only and conserve parcel
// volume, drag coefficient and momentum to round-off on 1-3 ranks; a gathered uniform field is exact; a
// parcel alone in a cut cell gives that cell its volume over the cell's fluid volume.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "cfd/mesh/mesh_builder.hpp"
#include "coupling/run/parcel_mesh_coupler.h"
#include "coupling/run/coupler_view.h"
#include "tests/unit/coupling/transfer_conservation.hpp"

namespace pc = parcelflow::coupling;
namespace cfd = parcelflow::cfd;

namespace {

constexpr double kPi = 3.14159265358979323846;

cfd::Mesh pipeMesh() {
  cfd::MeshSettings s;
  s.origin = cfd::Vec3(-0.6, -0.6, 0.0);
  s.lengths = cfd::Vec3(1.2, 1.2, 0.1);
  s.cells = {24, 24, 2};
  s.walls = cfd::WallRepresentation::CutCells;
  const cfd::Geometry pipe({{cfd::Geometry::Op::Union, cfd::Primitive::cylinder(0, 0, 0.5 + 5e-11, 0, 0.1), ""}});
  return cfd::MeshBuilder::build(s, pipe, MPI_COMM_WORLD);
}

// Parcels in the pipe, all of them within two cells of its wall.
struct Parcels {
  std::vector<double> x, v, dp, np;
  Parcels(int rank, int count) {
    std::mt19937 rng(11 + rank);
    std::uniform_real_distribution<double> ur(0.4, 0.4999), uphi(0.0, 2 * kPi), uz(0.001, 0.099), uv(-1.0, 1.0);
    while (static_cast<int>(dp.size()) < count) {
      const double r = ur(rng), phi = uphi(rng), z = uz(rng);
      x.insert(x.end(), {r * std::cos(phi), r * std::sin(phi), z});
      v.insert(v.end(), {uv(rng), uv(rng), uv(rng)});
      dp.push_back(1e-4 * (1.0 + (rng() % 5)));
      np.push_back(1.0 + (rng() % 27));
    }
  }
  pc::ParcelBatch batch() const { return {dp.size(), x.data(), v.data(), dp.data(), np.data()}; }
};

}  // namespace

class CutCellTransfer : public ::testing::TestWithParam<const char*> {};

TEST_P(CutCellTransfer, ConservesVolumeDragAndMomentumInFluidVolume) {
  const cfd::Mesh mesh = pipeMesh();
  ASSERT_GT(mesh.mergedCells(), 0);  // the merged cells are part of what is tested
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const pc::CellOwnerMap owners(MPI_COMM_WORLD, mesh.background().size(), pc::ownedPiecesOf(mesh));
  long cut = 0;  // background cells the wall cuts, as the owner map reports them
  for (long b = 0; b < owners.backgroundSize(); ++b)
    cut += owners.fluidFraction(b) > 0.0 && owners.fluidFraction(b) < 1.0;
  ASSERT_GT(cut, 0);
  pc::ParcelMeshCoupler coupler(pc::backgroundGridOf(mesh), owners, pc::makeTransferKernel(GetParam()), pc::makeDragLaw("WenYu"),
                                pc::DragLimits{0.3}, pc::GasProperties{1.2, 1.8e-5});
  for (int c = 0; c < mesh.nOwnedCells(); ++c) ASSERT_DOUBLE_EQ(coupler.ownedCellVolume(c), mesh.cellVolume(c)) << c;
  const Parcels parcels(rank, 600);
  const pc::TransferStats stats = coupler.beginStep(parcels.batch());
  EXPECT_EQ(pc::test::sumOverRanks(static_cast<double>(stats.orphans)), 0.0);

  const pc::test::ConservationErrors e = pc::test::transferConservation(coupler, parcels.batch(), mesh.nOwnedCells());
  int nranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &nranks);
  if (rank == 0)
    std::printf("[%s kernel, cut cells, %d rank(s), %ld merged] relative errors: volume %.2e, kappa %.2e, "
                "momentum %.2e; max gather error of a uniform field %.2e\n",
                GetParam(), nranks, mesh.mergedCells(), e.volume, e.kappa, e.momentum, e.gather);
  EXPECT_LT(e.volume, 1e-12);
  EXPECT_LT(e.kappa, 1e-12);
  EXPECT_LT(e.momentum, 1e-12);
  EXPECT_LT(e.gather, 1e-14);
}

INSTANTIATE_TEST_SUITE_P(Kernels, CutCellTransfer, ::testing::Values("gaussian", "centroid"));

// One parcel in a cut cell, centroid kernel: its whole volume lands in that gas cell, as a fraction of the
// cell's fluid volume (a staircase would divide by the whole background cell, or drop it).
TEST(CutCellTransfer, AParcelInACutCellFillsItsFluidVolume) {
  const cfd::Mesh mesh = pipeMesh();
  const pc::CellOwnerMap owners(MPI_COMM_WORLD, mesh.background().size(), pc::ownedPiecesOf(mesh));
  pc::ParcelMeshCoupler coupler(pc::backgroundGridOf(mesh), owners, pc::makeTransferKernel("centroid"), pc::makeDragLaw("WenYu"),
                                pc::DragLimits{0.3}, pc::GasProperties{1.2, 1.8e-5});
  // (0.48, 0.01, 0.025): in background cell (21, 12, 0), which the pipe's wall cuts at x = 0.4975-0.5
  const long cell = mesh.background().index(21, 12, 0);
  const double share = owners.fluidFraction(cell);
  ASSERT_GT(share, 0.0);
  ASSERT_LT(share, 1.0);
  const double x[3] = {0.48, 0.01, 0.025}, v[3] = {0, 0, 0}, dp = 1e-3, np = 10.0;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  coupler.beginStep(rank == 0 ? pc::ParcelBatch{1, x, v, &dp, &np} : pc::ParcelBatch{});
  std::vector<double> solid_fraction;
  coupler.depositSolids(solid_fraction);
  const double volume = np * kPi / 6 * dp * dp * dp;
  double found = 0.0;
  for (int c = 0; c < mesh.nOwnedCells(); ++c) {
    bool mine = false;
    for (int m = 0; m < mesh.nMembers(c); ++m) mine = mine || mesh.member(c, m) == cell;
    if (mine) {
      EXPECT_NEAR(solid_fraction[c], volume / mesh.cellVolume(c), 1e-15 * volume / mesh.cellVolume(c));
      EXPECT_LE(mesh.cellVolume(c), mesh.background().cellVolume() * (mesh.nMembers(c) - 1 + share) * (1 + 1e-12));
    } else {
      EXPECT_EQ(solid_fraction[c], 0.0) << c;
    }
    found += solid_fraction[c] * mesh.cellVolume(c);
  }
  EXPECT_NEAR(pc::test::sumOverRanks(found), volume, 1e-15 * volume);
}
