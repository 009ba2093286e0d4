// Verification 3: a blob of solids (a_s up to 0.4, Gaussian) moves up through a column while gas
// enters at the bottom. Every step the gas mass balance must close: the change of the gas volume
// sum a_g V over the step equals the net boundary inflow times dt, to 1e-10 relative.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "tests/regression/cfd/gas_case.hpp"

using namespace parcelflow::cfd;
using namespace parcelflow::cfd::testing;

namespace {
constexpr double kU = 0.1, kDt = 5e-3;
constexpr int kSteps = 20;

GasSettings boxSettings() {
  GasSettings s;
  s.mesh.lengths = Vec3(0.08, 0.08, 0.16);
  s.mesh.cells = {8, 8, 16};
  s.gas = {1.2, 1.8e-5, Vec3(0, 0, -9.81)};
  s.boundaries = {{"zmin", BoundaryType::VelocityInlet, Vec3(0, 0, kU), 0.0},
                  {"zmax", BoundaryType::PressureOutlet, Vec3::Zero(), 1e5},
                  {"xmin", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0},
                  {"xmax", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0},
                  {"ymin", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0},
                  {"ymax", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0}};
  tightSolvers(s);
  return s;
}

// Gas fraction at time t: the blob centre moves up at 1 m/s.
ScalarField blob(const Mesh& m, double t) {
  ScalarField alpha(m.nLocalCells());
  const Vec3 centre(0.04, 0.04, 0.04 + 1.0 * t);
  for (int c = 0; c < m.nLocalCells(); ++c)
    alpha[c] = 1.0 - 0.4 * std::exp(-(m.cellCentre(c) - centre).squaredNorm() / (0.02 * 0.02));
  return alpha;
}

struct BalanceRun {
  GlobalFields fields;
  double worstImbalance = 0.0;
};

BalanceRun runBlob(MPI_Comm comm) {
  GasSolver gas(boxSettings(), comm);
  const Mesh& m = gas.mesh();
  gas.setGasFraction(blob(m, 0.0));
  ScalarField beta(m.nLocalCells());
  BalanceRun run;
  for (int step = 0; step < kSteps; ++step) {
    const double before = gas.gasVolume();
    const ScalarField alpha = blob(m, (step + 1) * kDt);
    for (int c = 0; c < m.nLocalCells(); ++c) beta[c] = 2e4 * (1.0 - alpha[c]);
    gas.setGasFraction(alpha);
    gas.setDragCoefficient(beta);
    gas.setDragSource(VectorField(m.nLocalCells(), Vec3::Zero()));
    const StepReport r = gas.advance(kDt);
    const double dVdt = (gas.gasVolume() - before) / kDt;
    const double inflow = kU * 0.08 * 0.08;
    // d/dt (gas volume) = -(net outflow through the boundary)
    const double imbalance = std::abs(dVdt + r.boundaryOutflow) / inflow;
    run.worstImbalance = std::max(run.worstImbalance, imbalance);
  }
  run.fields = gather(gas);
  return run;
}
}  // namespace

TEST(MovingBlob, GasMassBalanceClosesEveryStep) {
  const BalanceRun run = runBlob(MPI_COMM_WORLD);
  if (isRoot())
    std::cout << "[measured] moving blob: worst |dV_gas/dt + net outflow| / inflow over " << kSteps
              << " steps = " << run.worstImbalance << std::endl;
  EXPECT_LT(run.worstImbalance, 1e-10);
  const double diff = rankAgreement([](MPI_Comm c) { return runBlob(c).fields; }, run.fields, 1e5, 0.0);
  if (worldSize() > 1) {
    EXPECT_LT(diff, 1e-10);
  }
}
