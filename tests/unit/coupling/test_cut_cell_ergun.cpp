// Ergun pressure drop of a packed cylinder on cut cells (issue 31, verification): a round column of radius
// 50 mm and 0.2 m on 12 x 12 x 20 background cells of 10 mm, its wall cut through the cells, filled with
// resting parcels on a cubic lattice (spacing 10/3 mm, each standing for 0.5 mm particles filling 55 % of
// its lattice cube), air entering at the bottom at U = 0.05 m/s. The parcels deposit into the cut cells'
// fluid volume, the Ergun law gives their drag from the gas they gather, the gas solver answers, repeated
// until steady, as a coupled run does without the DEM. With the centroid kernel the pressure gradient
// between z = 0.05 and 0.15 m must be Ergun's for the bed's mean gas fraction (total parcel volume over the
// column's fluid volume) within 3 %:
//   |dp/dz| = beta U / a_g^2 + rho g,  beta = 150 a_s^2 mu / (a_g d^2) + 1.75 a_s rho U / (a_g d).
// The second test holds what the truncated Gaussian kernel does at the cut wall, the third what reflecting it does.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "cfd/solver/gas_solver.hpp"
#include "coupling/run/coupler_view.h"
#include "tests/unit/coupling/transfer_conservation.hpp"

namespace pc = parcelflow::coupling;
namespace cfd = parcelflow::cfd;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 0.05, kHeight = 0.2, kU = 0.05, kRho = 1.2, kMu = 1.8e-5, kG = 9.81;
constexpr double kDiameter = 0.5e-3, kSpacing = 0.01 / 3, kLatticeSolids = 0.55;

cfd::GasSettings columnSettings() {
  cfd::GasSettings s;
  s.mesh.origin = cfd::Vec3(-0.06, -0.06, 0.0);
  s.mesh.lengths = cfd::Vec3(0.12, 0.12, kHeight);
  s.mesh.cells = {12, 12, 20};
  s.mesh.walls = cfd::WallRepresentation::CutCells;
  s.geometry = cfd::Geometry({{cfd::Geometry::Op::Union, cfd::Primitive::cylinder(0, 0, kRadius, 0, kHeight), ""}});
  s.gas = {kRho, kMu, cfd::Vec3(0, 0, -kG)};
  s.boundaries = {{"zmin", cfd::BoundaryType::VelocityInlet, cfd::Vec3(0, 0, kU), 0.0},
                  {"zmax", cfd::BoundaryType::PressureOutlet, cfd::Vec3::Zero(), 1e5},
                  {"walls", cfd::BoundaryType::NoSlipWall, cfd::Vec3::Zero(), 0.0}};
  return s;
}

// This rank's share of the lattice points inside the column (every size-th point, round robin).
struct LatticeParcels {
  std::vector<double> x, v, dp, np;
  LatticeParcels(int rank, int size) {
    const double count = kLatticeSolids * std::pow(kSpacing, 3) / (kPi / 6 * std::pow(kDiameter, 3));
    long index = 0;
    const int across = static_cast<int>(std::round(2 * kRadius / kSpacing)),
              along = static_cast<int>(std::round(kHeight / kSpacing));
    for (int k = 0; k < along; ++k)
      for (int j = 0; j < across; ++j)
        for (int i = 0; i < across; ++i) {
          const double px = -kRadius + (i + 0.5) * kSpacing, py = -kRadius + (j + 0.5) * kSpacing;
          if (px * px + py * py >= kRadius * kRadius || index++ % size != rank) continue;
          x.insert(x.end(), {px, py, (k + 0.5) * kSpacing});
          v.insert(v.end(), {0.0, 0.0, 0.0});
          dp.push_back(kDiameter);
          np.push_back(count);
        }
  }
  pc::ParcelBatch batch() const { return {dp.size(), x.data(), v.data(), dp.data(), np.data()}; }
};

// Volume-weighted mean pressure of the cells whose centre lies within 5 mm of height z.
double layerPressure(const cfd::GasSolver& gas, double z) {
  const cfd::Mesh& m = gas.mesh();
  double pv = 0, v = 0;
  for (int c = 0; c < m.nOwnedCells(); ++c)
    if (std::abs(m.cellCentre(c)[2] - z) < 0.005) {
      pv += gas.pressure()[c] * m.cellVolume(c);
      v += m.cellVolume(c);
    }
  return m.sum(pv) / m.sum(v);
}

pc::TransferKernelOptions kernelOptions(bool reflect) {
  pc::TransferKernelOptions options;
  options.gaussianReflectAtWalls = reflect;
  return options;
}

struct ErgunRun {
  double meanSolids, wallCellSolids, measured, ergun;  // wallCellSolids: the lowest a_s of a cell
};

ErgunRun runPackedCylinder(const char* kernel, bool reflect = false) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  cfd::GasSolver gas(columnSettings(), MPI_COMM_WORLD);
  const cfd::Mesh& mesh = gas.mesh();
  const pc::CellOwnerMap owners(MPI_COMM_WORLD, mesh.background().size(), pc::ownedPiecesOf(mesh));
  pc::ParcelMeshCoupler coupler(pc::backgroundGridOf(mesh), owners, pc::makeTransferKernel(kernel, kernelOptions(reflect)),
                                pc::makeDragLaw("Ergun"), pc::DragLimits{0.3}, pc::GasProperties{kRho, kMu});
  const LatticeParcels parcels(rank, size);
  const pc::TransferStats stats = coupler.beginStep(parcels.batch());
  EXPECT_EQ(pc::test::sumOverRanks(static_cast<double>(stats.orphans)), 0.0);
  const int n = mesh.nOwnedCells();
  std::vector<double> solids;
  coupler.depositSolids(solids);
  cfd::ScalarField gasFraction(n);
  double parcelVolume = 0, fluidVolume = 0;
  for (int c = 0; c < n; ++c) {
    gasFraction[c] = 1.0 - solids[c];
    parcelVolume += solids[c] * mesh.cellVolume(c);
    fluidVolume += mesh.cellVolume(c);
  }
  const double meanSolids = mesh.sum(parcelVolume) / mesh.sum(fluidVolume);
  gas.setGasFraction(gasFraction);
  gas.setDragSource(cfd::VectorField(n, cfd::Vec3::Zero()));

  // Drag relaxes the gas in rho a_g / beta ~ 1e-4 s; 40 steps of 5 ms reach the steady state, each with
  // the drag of the gas the step before left.
  pc::SolidsOnCells onCells;
  pc::GasAtParcels atParcels;
  std::vector<double> velocity(3 * n);
  for (int step = 0; step < 40; ++step) {
    for (int c = 0; c < n; ++c)
      for (int d = 0; d < 3; ++d) velocity[3 * c + d] = gas.velocity()[c][d];
    coupler.computeDrag(gasFraction, velocity, onCells, atParcels);
    gas.setDragCoefficient(onCells.beta);
    gas.advance(5e-3);
  }

  const double aG = 1.0 - meanSolids, aS = meanSolids;
  const double beta = 150 * aS * aS * kMu / (aG * kDiameter * kDiameter) + 1.75 * aS * kRho * kU / (aG * kDiameter);
  const double lowest = 1.0 - *std::max_element(gasFraction.begin(), gasFraction.end());
  ErgunRun r{meanSolids, -mesh.max(-lowest), 0.0, beta * kU / (aG * aG) + kRho * kG};
  r.measured = (layerPressure(gas, 0.055) - layerPressure(gas, 0.145)) / 0.09;
  if (rank == 0)
    std::printf("[measured] packed cylinder on cut cells, %s kernel%s, %d rank(s): mean solids fraction %.4f (lattice "
                "%.2f), lowest cell %.3f; |dp/dz| %.1f Pa/m against Ergun's %.1f (%+.2f %%)\n",
                kernel, reflect ? " (reflect)" : "", size, r.meanSolids, kLatticeSolids, r.wallCellSolids, r.measured, r.ergun,
                100 * (r.measured / r.ergun - 1));
  return r;
}

}  // namespace

// The centroid kernel puts each parcel's volume into the cell of its centre: the cut cells along the wall hold
// what lies in them, and the pressure gradient is Ergun's (measured -1.53 %).
TEST(CutCellErgun, PackedCylinderPressureDropWithinThreePercent) {
  const ErgunRun r = runPackedCylinder("centroid");
  EXPECT_NEAR(r.measured / r.ergun, 1.0, 0.03);
  EXPECT_GT(r.wallCellSolids, 0.5);
}

// The Gaussian kernel (truncated at walls, renormalised over the fluid it reaches) moves the solids of
// parcels near a cut wall inwards: the wall's cells get 0.43-0.49 at mid-height where the bed has 0.55, the next ring
// 0.60-0.61, and the gas passes along the wall (measured -5.48 %, cfd/README.md). What this test holds is
// that shift, so that a change of it shows: the wall cells below the bed's solids fraction, the pressure
// gradient below the centroid kernel's and not more than 10 % below Ergun's.
TEST(CutCellErgun, GaussianKernelThinsTheWallCells) {
  const ErgunRun centroid = runPackedCylinder("centroid");
  const ErgunRun gaussian = runPackedCylinder("gaussian");
  EXPECT_LT(gaussian.wallCellSolids, 0.5);
  EXPECT_LT(gaussian.measured, centroid.measured);
  EXPECT_GT(gaussian.measured / gaussian.ergun, 0.9);
}

// Reflecting the Gaussian at the cut (coupling.kernel.boundary: reflect; the wall where the parcel's row leaves
// the fluid, inside the last cut cell at its fluid share) puts the solids back at the wall: Ergun's gradient
// within 3 % as with the centroid kernel (measured -0.35 %, lowest cell 0.514; reflected at the cut cells'
// outer faces instead, -4.24 % and 0.348).
TEST(CutCellErgun, ReflectingGaussianKernelKeepsTheWallCells) {
  const ErgunRun reflected = runPackedCylinder("gaussian", true);
  EXPECT_NEAR(reflected.measured / reflected.ergun, 1.0, 0.03);
  EXPECT_GT(reflected.wallCellSolids, 0.5);
}
