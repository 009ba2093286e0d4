// The gas temperature equation (cfd::GasEnergy) on 1, 2 and 3 ranks: a closed box of gas and parcels
// (exchange and conduction only) keeps its energy to round-off and mixes without overshoot; conduction
// between two walls held at 300 K and 400 K gives the exact linear profile; a flow from a hot inlet
// closes its energy balance (what the patches carried in = what the gas holds more) and ends at the
// inlet temperature.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "cfd/solver/gas_energy.hpp"
#include "cfd/solver/gas_solver.hpp"
#include "cfd/mesh/mesh_builder.hpp"

using namespace parcelflow::cfd;

namespace {

constexpr double kRho = 1.2, kC = 1005.0, kK = 0.026;

GasSettings box(int n, const std::vector<BoundarySettings>& boundaries) {
  GasSettings s;
  s.mesh.origin = Vec3::Zero();
  s.mesh.lengths = Vec3(0.1, 0.1, 0.1);
  s.mesh.cells = {n, n, n};
  s.gas = {kRho, 1.8e-5, Vec3(0, 0, -9.81)};
  s.boundaries = boundaries;
  for (LinearSolverSettings* l : {&s.solver.pressure, &s.solver.momentum}) {
    l->criterion = StoppingCriterion::Strict;
    l->relTolerance = 1e-12;
  }
  return s;
}

std::vector<BoundarySettings> wallsAndOutlet() {
  return {{"xmin", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0}, {"xmax", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0},
          {"ymin", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0}, {"ymax", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0},
          {"zmin", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0}, {"zmax", BoundaryType::PressureOutlet, Vec3::Zero(), 0.0}};
}

double sumAll(double v) {
  double r = 0.0;
  MPI_Allreduce(&v, &r, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  return r;
}
double maxAll(double v) {
  double r = 0.0;
  MPI_Allreduce(&v, &r, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return r;
}
bool root() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r == 0;
}

}  // namespace

TEST(GasEnergy, ClosedBoxOfGasAndParcelsKeepsItsEnergy) {
  const GasSettings s = box(6, wallsAndOutlet());
  auto mesh = std::make_shared<const Mesh>(MeshBuilder::build(s.mesh, s.geometry, MPI_COMM_WORLD));
  GasThermalSettings thermal;
  thermal.heatCapacity = kC;
  thermal.conductivity = kK;
  thermal.initialTemperature = 300.0;
  thermal.solver.relTolerance = 1e-15;  // the energy changes by the linear solve's residual: make it round-off
  GasEnergy gas(mesh, kRho, s.boundaries, thermal);
  const int n = mesh->nOwnedCells();
  const double alpha = 0.6, dt = 0.01;
  // the gas warm on one side (conduction inside), one parcel per cell at 400 K holding 10 times the
  // cell gas's heat capacity, with dt H/(M c) = 5 (a fine particle's response far below the step)
  ScalarField T0(n), alphaField(n, alpha), phi(mesh->nInternalFaces(), 0.0), phiB(mesh->nBoundaryFaces(), 0.0);
  for (int c = 0; c < n; ++c) T0[c] = 300.0 + 500.0 * mesh->cellCentre(c)[0];
  gas.setTemperature(T0);
  gas.setGasFraction(alphaField);
  std::vector<double> mc(n), Tp(n, 400.0), Heff(n), coeff(n), source(n);
  double parcels = 0.0;
  for (int c = 0; c < n; ++c) {
    mc[c] = 10.0 * kRho * kC * alpha * mesh->cellVolume(c);
    parcels += mc[c] * Tp[c];
  }
  const double H = 5.0 * mc[0] / dt;
  // the coupled implicit Euler step of gas and parcel: the gas sees H_eff = H M c/(M c + dt H)
  for (int c = 0; c < n; ++c) Heff[c] = H * mc[c] / (mc[c] + dt * H);
  const double e0 = gas.heatContent() + sumAll(parcels);
  double worst = 0.0, lo = 1e300, hi = -1e300;
  for (int step = 0; step < 30; ++step) {
    for (int c = 0; c < n; ++c) {
      coeff[c] = Heff[c];
      source[c] = Heff[c] * Tp[c];
    }
    const EnergyStepReport r = gas.advance(dt, alphaField, phi, phiB, coeff, source);
    EXPECT_TRUE(r.converged);
    parcels = 0.0;
    for (int c = 0; c < n; ++c) {
      Tp[c] += dt * Heff[c] * (gas.temperature()[c] - Tp[c]) / mc[c];
      parcels += mc[c] * Tp[c];
      lo = std::min({lo, Tp[c], gas.temperature()[c]});
      hi = std::max({hi, Tp[c], gas.temperature()[c]});
    }
    const double e = gas.heatContent() + sumAll(parcels);
    worst = std::max(worst, std::fabs(e - e0) / e0);
  }
  lo = -maxAll(-lo);
  hi = maxAll(hi);
  if (root())
    std::printf("[ gas energy ] closed box, 30 steps, dt H/(M c) = 5: max |E - E0|/E0 = %.1e; temperatures in "
                "[%.4f, %.4f] K (started in [300, 350] and 400)\n", worst, lo, hi);
  EXPECT_LT(worst, 1e-13);
  EXPECT_GE(lo, 300.0 - 1e-9);
  EXPECT_LE(hi, 400.0 + 1e-9);
}

TEST(GasEnergy, ConductionBetweenTwoWallsIsLinear) {
  std::vector<BoundarySettings> b = wallsAndOutlet();
  const GasSettings s = box(8, b);
  auto mesh = std::make_shared<const Mesh>(MeshBuilder::build(s.mesh, s.geometry, MPI_COMM_WORLD));
  GasThermalSettings thermal;
  thermal.heatCapacity = kC;
  thermal.conductivity = kK;
  thermal.initialTemperature = 350.0;
  thermal.patches = {{"xmin", 300.0}, {"xmax", 400.0}};
  GasEnergy gas(mesh, kRho, s.boundaries, thermal);
  const int n = mesh->nOwnedCells();
  ScalarField alpha(n, 1.0), zero(n, 0.0), phi(mesh->nInternalFaces(), 0.0), phiB(mesh->nBoundaryFaces(), 0.0);
  EnergyStepReport r;
  for (int step = 0; step < 20; ++step) r = gas.advance(1e6, alpha, phi, phiB, zero, zero);  // steady
  double err = 0.0;
  for (int c = 0; c < n; ++c)
    err = std::max(err, std::fabs(gas.temperature()[c] - (300.0 + 1000.0 * mesh->cellCentre(c)[0])));
  err = maxAll(err);
  if (root())
    std::printf("[ gas energy ] walls at 300 and 400 K: max |T - linear| = %.1e K; net wall heat %.1e W of %.4f W "
                "through the gas\n", err, r.wallConduction, kK * 0.01 * 100.0 / 0.1);
  EXPECT_LT(err, 1e-8);
  EXPECT_LT(std::fabs(r.wallConduction), 1e-9);
}

TEST(GasEnergy, FlowFromAHotInletClosesItsBalance) {
  std::vector<BoundarySettings> b = wallsAndOutlet();
  b[4] = {"zmin", BoundaryType::VelocityInlet, Vec3(0, 0, 0.05), 0.0};
  const GasSettings s = box(6, b);
  auto mesh = std::make_shared<const Mesh>(MeshBuilder::build(s.mesh, s.geometry, MPI_COMM_WORLD));
  GasSolver flow(s, mesh);
  GasThermalSettings thermal;
  thermal.heatCapacity = kC;
  thermal.conductivity = kK;
  thermal.initialTemperature = 300.0;
  thermal.patches = {{"zmin", 350.0}};
  GasEnergy gas(mesh, kRho, s.boundaries, thermal);
  const int n = mesh->nOwnedCells();
  const ScalarField zero(n, 0.0);
  const double dt = 0.05;
  const double e0 = gas.heatContent();
  double carried = 0.0, throughput = 0.0;
  for (int step = 0; step < 200; ++step) {
    flow.advance(dt);
    const GasSolver::State st = flow.state();
    const EnergyStepReport r = gas.advance(dt, st.alpha, st.phi, st.phiBoundary, zero, zero);
    carried += dt * r.boundaryConvection;
    throughput += dt * kRho * kC * 0.05 * 0.01 * 350.0;
  }
  const double imbalance = std::fabs(gas.heatContent() - e0 - carried) / throughput;
  double off = 0.0;
  for (int c = 0; c < n; ++c) off = std::max(off, std::fabs(gas.temperature()[c] - 350.0));
  off = maxAll(off);
  if (root())
    std::printf("[ gas energy ] hot inlet, 200 steps (10 s, 5 flow-throughs): |E - E0 - carried in| = %.1e of the "
                "throughput; max |T - 350 K| at the end %.2e K\n", imbalance, off);
  EXPECT_LT(imbalance, 1e-10);
  EXPECT_LT(off, 1e-3);
}
