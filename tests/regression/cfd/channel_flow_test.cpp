// Verification 1: laminar plane channel flow (a_g = 1) driven by a body force along x between two
// no-slip walls at y = 0 and y = H; both ends are pressure outlets at p = 0, so the flow is fully
// developed everywhere: u(y) = rho g y (H - y) / (2 mu). Checks the profile error at 20 cells across
// (< 1 %) and measures the order of convergence under refinement.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "tests/regression/cfd/gas_case.hpp"

using namespace parcelflow::cfd;
using namespace parcelflow::cfd::testing;

namespace {
constexpr double kRho = 1.0, kMu = 0.1, kG = 0.1, kH = 1.0;

GasSettings channelSettings(int ny) {
  GasSettings s;
  s.mesh.origin = Vec3::Zero();
  s.mesh.lengths = Vec3(0.4, kH, 0.1);
  s.mesh.cells = {4, ny, 1};
  s.gas = {kRho, kMu, Vec3(kG, 0, 0)};
  s.boundaries = {{"xmin", BoundaryType::PressureOutlet, Vec3::Zero(), 0.0},
                  {"xmax", BoundaryType::PressureOutlet, Vec3::Zero(), 0.0},
                  {"ymin", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0},
                  {"ymax", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0},
                  {"zmin", BoundaryType::FreeSlipWall, Vec3::Zero(), 0.0},
                  {"zmax", BoundaryType::FreeSlipWall, Vec3::Zero(), 0.0}};
  tightSolvers(s);
  return s;
}

GlobalFields runChannel(int ny, MPI_Comm comm) {
  GasSolver gas(channelSettings(ny), comm);
  // dt = 0.5 s is half the slowest diffusive decay time H^2 / (pi^2 nu) = 1 s; 250 steps bring the
  // transient below 1e-10 of u_max.
  for (int step = 0; step < 250; ++step) gas.advance(0.5);
  return gather(gas);
}

double profileError(const GlobalFields& f) {
  const double umax = kRho * kG * kH * kH / (8 * kMu);
  double err = 0;
  for (std::size_t i = 0; i < f.ux.size(); ++i) {
    const double y = f.centre[i][1];
    const double exact = kRho * kG * y * (kH - y) / (2 * kMu);
    err = std::max(err, std::abs(f.ux[i] - exact));
  }
  return err / umax;
}
}  // namespace

TEST(ChannelFlow, ProfileWithinOnePercentAndSecondOrder) {
  const GlobalFields f10 = runChannel(10, MPI_COMM_WORLD);
  const GlobalFields f20 = runChannel(20, MPI_COMM_WORLD);
  const GlobalFields f40 = runChannel(40, MPI_COMM_WORLD);
  if (isRoot()) {
    const double e10 = profileError(f10), e20 = profileError(f20), e40 = profileError(f40);
    const double order1 = std::log2(e10 / e20), order2 = std::log2(e20 / e40);
    std::cout << "[measured] channel flow max profile error / u_max: 10 cells " << e10
              << ", 20 cells " << e20 << ", 40 cells " << e40 << "; observed order " << order1
              << " (10->20), " << order2 << " (20->40)" << std::endl;
    EXPECT_LT(e20, 0.01);
    EXPECT_GT(order2, 1.8);
  }
  const double diff = rankAgreement([](MPI_Comm c) { return runChannel(20, c); }, f20,
                                   kRho * kG * 0.4, 0.0);
  if (worldSize() > 1) {
    EXPECT_LT(diff, 1e-10);
  }
}
