// Verification 5: a cylinder column with a narrower exit tube (union of two cylinders), closed at the
// bottom, fed only by a ring sparger (inlet region = cylinder cut by a smaller cylinder) that injects
// a given flow downwards. Every step the outflow through the tube's top must equal the injected flow
// to 1e-10 relative.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "tests/regression/cfd/gas_case.hpp"

using namespace parcelflow::cfd;
using namespace parcelflow::cfd::testing;

namespace {
constexpr double kQ = 2e-3;  // m^3/s
constexpr int kSteps = 15;

GasSettings columnSettings() {
  GasSettings s;
  s.mesh.origin = Vec3(-0.12, -0.12, 0.0);
  s.mesh.lengths = Vec3(0.24, 0.24, 0.5);
  s.mesh.cells = {12, 12, 25};
  s.geometry = Geometry({{Geometry::Op::Union, Primitive::cylinder(0, 0, 0.1, 0, 0.4), ""},
                         {Geometry::Op::Union, Primitive::cylinder(0, 0, 0.04, 0.4, 0.5), ""}});
  s.gas = {1.2, 1.8e-5, Vec3(0, 0, -9.81)};
  s.boundaries = {{"zmin", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0},
                  {"walls", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0},
                  {"zmax", BoundaryType::PressureOutlet, Vec3::Zero(), 1e5}};
  InletRegionSettings ring;
  ring.name = "sparger";
  ring.region = Geometry({{Geometry::Op::Union, Primitive::cylinder(0, 0, 0.08, 0.04, 0.06), ""},
                          {Geometry::Op::Cut, Primitive::cylinder(0, 0, 0.05, 0.0, 0.1), ""}});
  ring.flowRate = kQ;
  ring.velocity = Vec3(0, 0, -2.0);
  s.inletRegions = {ring};
  tightSolvers(s);
  return s;
}

struct SpargerRun {
  GlobalFields fields;
  double worst = 0.0, cfl = 0.0;
  long cells = 0;
};

SpargerRun runColumn(MPI_Comm comm) {
  GasSolver gas(columnSettings(), comm);
  SpargerRun run;
  run.cells = gas.mesh().nGlobalCells();
  for (int step = 0; step < kSteps; ++step) {
    const StepReport r = gas.advance(5e-3);
    const double outlet = gas.patchOutflow("zmax");
    run.worst = std::max(run.worst, std::abs(outlet - kQ) / kQ);
    run.worst = std::max(run.worst, std::abs(r.injectedFlow - kQ) / kQ);
    run.cfl = r.cfl;
  }
  run.fields = gather(gas);
  return run;
}
}  // namespace

TEST(Sparger, OutletFlowEqualsInjectedFlow) {
  const SpargerRun run = runColumn(MPI_COMM_WORLD);
  if (isRoot())
    std::cout << "[measured] sparger column (" << run.cells << " cells): worst |Q_out - Q_in| / Q_in"
              << " over " << kSteps << " steps = " << run.worst << " (last CFL " << run.cfl << ")"
              << std::endl;
  EXPECT_LT(run.worst, 1e-10);
  const double diff =
      rankAgreement([](MPI_Comm c) { return runColumn(c).fields; }, run.fields, 1e5, 0.0);
  if (worldSize() > 1) {
    EXPECT_LT(diff, 1e-10);
  }
}

// ramp_time: the sparger's flow and a velocity inlet's rise linearly from 0; every step the outflow equals
// the inflow at the step's new time level, min(1, t / ramp) of the full flow (implicit Euler).
TEST(Sparger, RampedInletsFollowTheRamp) {
  constexpr double kDt = 5e-3, kRamp = 0.04, kInletU = 0.01;
  GasSettings s = columnSettings();
  s.inletRegions[0].rampTime = kRamp;
  s.boundaries[0] = {"zmin", BoundaryType::VelocityInlet, Vec3(0, 0, kInletU), 0.0, 2 * kRamp};
  GasSolver gas(s, MPI_COMM_WORLD);
  double plate = 0.0;  // area of the column's bottom faces
  const Mesh& m = gas.mesh();
  for (int b = 0; b < m.nBoundaryFaces(); ++b)
    if (m.patchNames()[m.boundaryPatch(b)] == "zmin") plate += m.boundaryMagArea(b);
  plate = m.sum(plate);
  double worst = 0.0;
  for (int step = 1; step <= kSteps; ++step) {
    const double t = step * kDt;
    const double expected = std::min(1.0, t / kRamp) * kQ + std::min(1.0, t / (2 * kRamp)) * kInletU * plate;
    const StepReport r = gas.advance(kDt);
    EXPECT_NEAR(r.injectedFlow, std::min(1.0, t / kRamp) * kQ, 1e-12 * kQ) << "step " << step;
    worst = std::max(worst, std::abs(gas.patchOutflow("zmax") - expected) / expected);
  }
  if (isRoot())
    std::cout << "[measured] ramped sparger and plate inlet: worst |Q_out - Q_in(t)| / Q_in(t) over " << kSteps
              << " steps = " << worst << std::endl;
  EXPECT_LT(worst, 1e-10);
}
