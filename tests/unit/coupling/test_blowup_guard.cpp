// BlowupGuard (coupling/run/blowup_guard.h): a non-finite gas velocity in one cell of one rank stops every
// rank with a message that names the quantity, the cell centre, the time, the step and the last checkpoint;
// a finite state passes; a Courant number above its limit on a cut-cell mesh points to the known defect of
// films left by a wall a hair off a cell face. (The Courant, continuity and parcel-loss limits are run end to end in
// tests/regression/reliability/blowup_guard.py.)
#include <gtest/gtest.h>
#include <mpi.h>

#include <limits>
#include <string>

#include <yaml-cpp/yaml.h>

#include "coupling/run/blowup_guard.h"
#include "cfd/solver/gas_config.hpp"

using namespace parcelflow;

namespace {

cfd::GasSettings boxColumn() {
  cfd::GasSettings s;
  s.mesh.lengths = cfd::Vec3(0.1, 0.1, 0.4);
  s.mesh.cells = {3, 3, 8};
  s.gas = {1.2, 1.8e-5, cfd::Vec3(0, 0, -9.81)};
  s.boundaries = {{"zmin", cfd::BoundaryType::VelocityInlet, cfd::Vec3(0, 0, 0.1), 0.0},
                  {"zmax", cfd::BoundaryType::PressureOutlet, cfd::Vec3::Zero(), 0.0}};
  for (const char* wall : {"xmin", "xmax", "ymin", "ymax"})
    s.boundaries.push_back({wall, cfd::BoundaryType::NoSlipWall, cfd::Vec3::Zero(), 0.0});
  return s;
}

// The guard's message on this rank, or "" if it did not stop the run.
std::string guardMessage(const cfd::GasSolver& gas, const cfd::StepReport& report) {
  coupling::BlowupGuard guard(MPI_COMM_WORLD, coupling::GuardSettings{}, 100);
  try {
    guard.check(&gas, report, 100, 0.25, 7, "out/checkpoints/step_000000005");
  } catch (const coupling::DivergedError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(BlowupGuard, AFiniteStatePasses) {
  cfd::GasSolver gas(boxColumn(), MPI_COMM_WORLD);
  const cfd::StepReport report = gas.advance(1e-3);
  EXPECT_EQ(guardMessage(gas, report), "");
}

TEST(BlowupGuard, ANonFiniteVelocityOnOneRankStopsEveryRankAndSaysWhere) {
  cfd::GasSolver gas(boxColumn(), MPI_COMM_WORLD);
  const cfd::StepReport report = gas.advance(1e-3);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  cfd::VectorField u = gas.velocity();
  const int last = size - 1;  // only the last rank's first cell goes bad
  if (rank == last && gas.mesh().nOwnedCells() > 0) u[0][2] = std::numeric_limits<double>::quiet_NaN();
  gas.setVelocity(u);
  const std::string message = guardMessage(gas, report);
  EXPECT_NE(message.find("t = 0.25 s (gas step 7)"), std::string::npos) << message;
  EXPECT_NE(message.find("non-finite gas velocity"), std::string::npos) << message;
  EXPECT_NE(message.find("at cell centre ("), std::string::npos) << message;
  EXPECT_NE(message.find("out/checkpoints/step_000000005"), std::string::npos) << message;
  // The cell centre is the bad cell's, on every rank.
  double centre[3] = {0, 0, 0};
  if (rank == last) for (int d = 0; d < 3; ++d) centre[d] = gas.mesh().cellCentre(0)[d];
  MPI_Bcast(centre, 3, MPI_DOUBLE, last, MPI_COMM_WORLD);
  char where[128];
  std::snprintf(where, sizeof where, "at cell centre (%g, %g, %g)", centre[0], centre[1], centre[2]);
  EXPECT_NE(message.find(where), std::string::npos) << message << " / " << where;
}

TEST(BlowupGuard, ACourantNumberAboveItsLimitOnCutCellsPointsToTheirKnownDefect) {
  // a pipe of radius 0.05 m on 12 x 12 x 2 cut cells, and the box column of whole cells
  const cfd::GasSettings pipe = cfd::GasConfig(YAML::Load(R"(
mesh: {origin: [-0.06, -0.06, 0.0], lengths: [0.12, 0.12, 0.02], cells: [12, 12, 2], walls: cut_cells}
geometry: [{shape: {cylinder: {center: [0, 0], radius: 0.05, zmin: 0.0, zmax: 0.02}}}]
gas: {density: 1.2, viscosity: 1.8e-5, gravity: [0, 0, -9.81]}
boundaries: {zmin: {type: velocity_inlet, superficial_velocity: [0, 0, 0.1]}, zmax: {type: pressure_outlet},
             walls: {type: wall}}
)")).settings();
  for (const bool cut : {true, false}) {
    cfd::GasSolver gas(cut ? pipe : boxColumn(), MPI_COMM_WORLD);
    cfd::StepReport report = gas.advance(1e-3);
    report.cfl = 2e3;  // above the default limit of 1000
    const std::string message = guardMessage(gas, report);
    EXPECT_NE(message.find("gas Courant number 2000 above coupling.guards.max_cfl = 1000"), std::string::npos)
        << message;
    EXPECT_EQ(message.find("Known defect: a wall a hair off a cell face") != std::string::npos, cut) << message;
  }
}
