// Convection scheme check: a step in the transverse velocity u_y is carried along x by a uniform
// plug flow (u_x = 1 m/s, inviscid limit). Both schemes must stay bounded (no new extrema), and the
// limited linear-upwind scheme must smear the step less than plain upwind.
#include <gtest/gtest.h>

#include <iostream>

#include "tests/regression/cfd/gas_case.hpp"

using namespace parcelflow::cfd;
using namespace parcelflow::cfd::testing;

namespace {
struct Profile {
  double minUy = 0, maxUy = 0, width = 0;  // width: cells with 0.05 < u_y < 0.95
};

Profile advect(ConvectionScheme scheme) {
  GasSettings s;
  s.mesh.lengths = Vec3(1.0, 0.1, 0.1);
  s.mesh.cells = {100, 1, 1};
  s.gas = {1.0, 1e-12, Vec3::Zero()};
  s.boundaries = {{"xmin", BoundaryType::VelocityInlet, Vec3(1, 0, 0), 0.0},
                  {"xmax", BoundaryType::PressureOutlet, Vec3::Zero(), 0.0},
                  {"ymin", BoundaryType::FreeSlipWall, Vec3::Zero(), 0.0},
                  {"ymax", BoundaryType::FreeSlipWall, Vec3::Zero(), 0.0},
                  {"zmin", BoundaryType::FreeSlipWall, Vec3::Zero(), 0.0},
                  {"zmax", BoundaryType::FreeSlipWall, Vec3::Zero(), 0.0}};
  s.solver.convection = scheme;
  tightSolvers(s);
  GasSolver gas(s, MPI_COMM_WORLD);
  const Mesh& m = gas.mesh();
  VectorField u(m.nLocalCells());
  for (int c = 0; c < m.nLocalCells(); ++c) u[c] = Vec3(1.0, m.cellCentre(c)[0] < 0.2 ? 1.0 : 0.0, 0);
  gas.setVelocity(u);
  for (int step = 0; step < 100; ++step) gas.advance(0.004);  // CFL 0.4, the step moves 0.4 m
  Profile p{1e30, -1e30, 0};
  double width = 0;
  for (int c = 0; c < m.nOwnedCells(); ++c) {
    const double uy = gas.velocity()[c][1];
    p.minUy = std::min(p.minUy, uy);
    p.maxUy = std::max(p.maxUy, uy);
    if (uy > 0.05 && uy < 0.95) width += 1;
  }
  p.minUy = -m.max(-p.minUy);
  p.maxUy = m.max(p.maxUy);
  p.width = m.sum(width);
  return p;
}
}  // namespace

TEST(Convection, BoundedAndLessDiffusiveWithLimiter) {
  const Profile up = advect(ConvectionScheme::Upwind);
  const Profile llu = advect(ConvectionScheme::LimitedLinearUpwind);
  if (isRoot())
    std::cout << "[measured] step advection: upwind u_y in [" << up.minUy << ", " << up.maxUy
              << "], smeared over " << up.width << " cells; limited linear upwind in [" << llu.minUy
              << ", " << llu.maxUy << "], smeared over " << llu.width << " cells" << std::endl;
  for (const auto& p : {up, llu}) {
    EXPECT_GT(p.minUy, -1e-10);
    EXPECT_LT(p.maxUy, 1.0 + 1e-10);
  }
  EXPECT_LT(llu.width, up.width);
}
