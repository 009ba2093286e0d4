// Schumann's packed bed through the gas temperature equation (cfd::GasEnergy, 1 and 2 ranks): plug flow
// of air through a bed of porosity 0.4 (uniform a_g, no conduction), the solid as each cell's lumped heat
// capacity exchanging h a_v V with the gas by the coupled implicit Euler step the coupling uses (the gas
// sees H_eff = H C_s/(C_s + dt H) toward the solid's old temperature, the solid then takes exactly what the
// gas gave). The outlet gas temperature against Schumann's solution (tests/support) at three resolutions
// (cells and steps refined together): within 2 % of T_in - T0 at the finest, with the observed order.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <memory>

#include "cfd/solver/gas_energy.hpp"
#include "cfd/mesh/mesh_builder.hpp"
#include "tests/support/schumann_packed_bed.hpp"

using namespace parcelflow::cfd;
using parcelflow::testing::SchumannBed;

namespace {

constexpr double kLength = 0.1, kSide = 0.01, kT0 = 300.0, kTin = 400.0, kEnd = 2500.0;

SchumannBed bed()
{
  SchumannBed b;  // air through glass, porosity 0.4
  b.interstitial_velocity = 0.25;
  // NTU of the bed h a_v L / (eps rho_g c_g u) = 10
  b.exchange = 10.0 * b.porosity * b.gas_density * b.gas_heat_capacity * b.interstitial_velocity / kLength;
  return b;
}

// max over the steps of |theta_outlet - theta_Schumann(L, t)|
double breakthroughError(int cells, double& breakthrough_time)
{
  const SchumannBed b = bed();
  GasSettings s;
  s.mesh.origin = Vec3::Zero();
  s.mesh.lengths = Vec3(kLength, kSide, kSide);
  s.mesh.cells = {cells, 1, 1};
  s.boundaries = {{"xmin", BoundaryType::VelocityInlet, Vec3::Zero(), 0.0},
                  {"xmax", BoundaryType::PressureOutlet, Vec3::Zero(), 0.0},
                  {"ymin", BoundaryType::FreeSlipWall, Vec3::Zero(), 0.0},
                  {"ymax", BoundaryType::FreeSlipWall, Vec3::Zero(), 0.0},
                  {"zmin", BoundaryType::FreeSlipWall, Vec3::Zero(), 0.0},
                  {"zmax", BoundaryType::FreeSlipWall, Vec3::Zero(), 0.0}};
  auto mesh = std::make_shared<const Mesh>(MeshBuilder::build(s.mesh, s.geometry, MPI_COMM_WORLD));
  GasThermalSettings thermal;
  thermal.heatCapacity = b.gas_heat_capacity;
  thermal.conductivity = 0.0;  // Schumann: no conduction
  thermal.initialTemperature = kT0;
  thermal.patches = {{"xmin", kTin}};
  GasEnergy gas(mesh, b.gas_density, s.boundaries, thermal);
  const int n = mesh->nOwnedCells();
  const double superficial = b.porosity * b.interstitial_velocity;
  ScalarField alpha(n, b.porosity), phi(mesh->nInternalFaces(), 0.0), phiB(mesh->nBoundaryFaces(), 0.0);
  for (int f = 0; f < mesh->nInternalFaces(); ++f)
    if (mesh->faceAxis(f) == 0) phi[f] = superficial * mesh->faceArea(f)[0];
  for (int f = 0; f < mesh->nBoundaryFaces(); ++f)
    if (mesh->patchNames()[mesh->boundaryPatch(f)] == "xmin" || mesh->patchNames()[mesh->boundaryPatch(f)] == "xmax")
      phiB[f] = superficial * std::fabs(mesh->boundaryArea(f)[0]) * (mesh->boundaryArea(f)[0] > 0 ? 1.0 : -1.0);
  gas.setGasFraction(alpha);
  // the outlet cell (owned by one rank)
  int outlet = -1;
  for (int c = 0; c < n; ++c)
    if (mesh->cellCentre(c)[0] > kLength - kLength / cells) outlet = c;
  const int steps = 4 * cells;
  const double dt = kEnd / steps;
  ScalarField Ts(n, kT0), coeff(n), source(n);
  std::vector<double> Cs(n), Heff(n);
  for (int c = 0; c < n; ++c) {
    const double V = mesh->cellVolume(c), H = b.exchange * V;
    Cs[c] = (1.0 - b.porosity) * b.solid_density * b.solid_heat_capacity * V;
    Heff[c] = H * Cs[c] / (Cs[c] + dt * H);
  }
  double err = 0.0;
  int unconverged = 0, max_iterations = 0;
  breakthrough_time = 0.0;
  for (int step = 1; step <= steps; ++step) {
    for (int c = 0; c < n; ++c) {
      coeff[c] = Heff[c];
      source[c] = Heff[c] * Ts[c];
    }
    const EnergyStepReport r = gas.advance(dt, alpha, phi, phiB, coeff, source);
    if (!r.converged) ++unconverged;
    max_iterations = std::max(max_iterations, r.iterations);
    for (int c = 0; c < n; ++c) Ts[c] += dt * Heff[c] * (gas.temperature()[c] - Ts[c]) / Cs[c];
    double theta = outlet >= 0 ? (gas.temperature()[outlet] - kT0) / (kTin - kT0) : -1.0, global = 0.0;
    MPI_Allreduce(&theta, &global, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    const double t = step * dt, exact = b.gas(kLength, t);
    err = std::max(err, std::fabs(global - exact));
    if (breakthrough_time == 0.0 && global >= 0.5) breakthrough_time = t;
  }
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf("[ schumann ] %d cells, %d steps: %d unconverged solves, at most %d iterations\n", cells, steps,
                unconverged, max_iterations);
  EXPECT_EQ(unconverged, 0);
  return err;
}

}  // namespace

// the time the outlet gas reaches theta = 1/2 in Schumann's solution
double exactBreakthrough()
{
  const SchumannBed b = bed();
  double lo = kLength / b.interstitial_velocity, hi = kEnd;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (b.gas(kLength, mid) < 0.5 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(SchumannBreakthrough, OutletWithinTwoPercentAtTheFinestResolution)
{
  double tb[3];
  const double e1 = breakthroughError(25, tb[0]), e2 = breakthroughError(50, tb[1]), e3 = breakthroughError(100, tb[2]);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf("[ schumann ] NTU 10, outlet breakthrough max |theta - Schumann| over %.0f s: 25 cells %.4f, 50 cells "
                "%.4f, 100 cells %.4f; observed order %.2f, %.2f; theta = 0.5 at %.0f / %.0f / %.0f s (Schumann's: "
                "%.1f s)\n",
                kEnd, e1, e2, e3, std::log2(e1 / e2), std::log2(e2 / e3), tb[0], tb[1], tb[2], exactBreakthrough());
  EXPECT_LT(e3, 0.02);
  EXPECT_GT(std::log2(e2 / e3), 0.8);
}
