// Verification: a velocity inlet through a distributor plate (boundaries.<patch>.distributor_pressure_drop).
// A 0.1 x 0.02 x 0.2 m column fed through its bottom plate at U = 0.2 m/s; the left half of its bottom
// 5 cm resists the gas (a drag coefficient, as a packed bed would). Every step:
// - the plate lets in exactly U A (1e-10 relative), as a fixed-velocity inlet would;
// - every face follows the plate's law u = (P - p) / R with one plenum pressure P and R = dp_plate / U
//   (u + p / R is the same on all faces, 1e-10 relative);
// and the split of the flow follows the plate's resistance: a plate much stiffer than the bed gives the
// uniform split of a fixed-velocity inlet, a softer plate sends more gas around the resisting half.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>

#include "cfd/base/config_error.hpp"
#include "tests/regression/cfd/gas_case.hpp"

using namespace parcelflow::cfd;
using namespace parcelflow::cfd::testing;

namespace {
constexpr double kU = 0.2, kLx = 0.1, kLy = 0.02;
constexpr int kSteps = 10;

GasSettings column(double plateDrop) {
  GasSettings s;
  s.mesh.lengths = Vec3(kLx, kLy, 0.2);
  s.mesh.cells = {10, 2, 20};
  s.gas = {1.2, 1.8e-5, Vec3(0, 0, -9.81)};
  s.boundaries = columnBoundaries(kU);
  for (auto& bc : s.boundaries)
    if (bc.patch == "zmin") bc.distributorPressureDrop = plateDrop;
  tightSolvers(s);
  return s;
}

struct PlateRun {
  double worstFlow = 0.0;       // |inflow - U A| / (U A), worst step
  double lawSpread = 0.0;       // (max - min) of u + p/R over the faces, relative to U, worst step
  double leftShare = 0.0;       // share of the inflow through x < Lx/2, last step
};

PlateRun run(double plateDrop, bool resistLeft) {
  GasSolver gas(column(plateDrop), MPI_COMM_WORLD);
  const Mesh& m = gas.mesh();
  ScalarField beta(m.nOwnedCells(), 0.0);
  for (int c = 0; c < m.nOwnedCells(); ++c)
    if (resistLeft && m.cellCentre(c)[0] < 0.5 * kLx && m.cellCentre(c)[2] < 0.05) beta[c] = 2e4;  // 200 Pa at U
  gas.setDragCoefficient(beta);
  const double R = plateDrop / kU;
  const int zmin = m.patchId("zmin");
  PlateRun out;
  for (int step = 0; step < kSteps; ++step) {
    gas.advance(1e-3);
    const GasSolver::State st = gas.state();
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, left = 0.0, all = 0.0;
    for (int b = 0; b < m.nBoundaryFaces(); ++b) {
      if (m.boundaryPatch(b) != zmin) continue;
      const double u = -st.phiBoundary[b] / m.boundaryMagArea(b);
      const double law = u + st.pRgh[m.boundaryCell(b)] / R;
      lo = std::min(lo, law);
      hi = std::max(hi, law);
      all += -st.phiBoundary[b];
      if (m.boundaryCentre(b)[0] < 0.5 * kLx) left += -st.phiBoundary[b];
    }
    MPI_Allreduce(MPI_IN_PLACE, &lo, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
    MPI_Allreduce(MPI_IN_PLACE, &hi, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    all = m.sum(all);
    out.worstFlow = std::max(out.worstFlow, std::abs(all - kU * kLx * kLy) / (kU * kLx * kLy));
    out.lawSpread = std::max(out.lawSpread, (hi - lo) / kU);
    out.leftShare = m.sum(left) / all;
  }
  return out;
}
}  // namespace

TEST(Distributor, ExactFlowAndThePlateLawOnEveryFace) {
  for (double drop : {1.0, 50.0, 1e4}) {
    const PlateRun r = run(drop, true);
    if (isRoot())
      std::cout << "[measured] plate pressure drop " << drop << " Pa: flow error " << r.worstFlow
                << ", spread of u + p/R " << r.lawSpread << " U, share of the flow through the resisting half "
                << r.leftShare << std::endl;
    EXPECT_LT(r.worstFlow, 1e-10) << drop;
    EXPECT_LT(r.lawSpread, 1e-10 * std::max(1.0, 1e4 / drop)) << drop;
  }
}

TEST(Distributor, TheSplitFollowsThePlateResistance) {
  const double soft = run(1.0, true).leftShare, medium = run(50.0, true).leftShare,
               stiff = run(1e6, true).leftShare, uniformBed = run(50.0, false).leftShare;
  if (isRoot())
    std::cout << "[measured] share through the resisting half: plate 1 Pa " << soft << ", 50 Pa " << medium
              << ", 1e6 Pa " << stiff << "; without the resisting bed " << uniformBed << std::endl;
  EXPECT_LT(soft, medium);
  EXPECT_LT(medium, stiff);
  EXPECT_LT(soft, 0.45);  // the bed's 200 Pa against a 1 Pa plate: most gas goes around
  EXPECT_NEAR(stiff, 0.5, 1e-3);
  EXPECT_NEAR(uniformBed, 0.5, 1e-10);
}

// A plate velocity with a component along the plate is refused on every rank alike (only the ranks that own
// faces of the plate can see it), naming the key.
TEST(Distributor, ATangentialPlateVelocityIsRefusedOnEveryRank) {
  GasSettings s = column(50.0);
  for (auto& bc : s.boundaries)
    if (bc.patch == "zmin") bc.superficialVelocity = Vec3(0.05, 0, kU);
  std::string message;
  try {
    GasSolver gas(s, MPI_COMM_WORLD);
  } catch (const ConfigError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("boundaries.zmin.superficial_velocity"), std::string::npos) << message;
}
