// Verification 4: gas at rest under gravity in a cylinder column (staircase walls) with a frozen,
// non-uniform bed (a_g and beta vary, u_s = 0): the pressure must stay hydrostatic to round-off and
// no velocity may appear.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "tests/regression/cfd/gas_case.hpp"

using namespace parcelflow::cfd;
using namespace parcelflow::cfd::testing;

namespace {
constexpr double kRho = 1.2, kG = 9.81, kH = 0.4, kPout = 1e5;

GasSettings columnSettings() {
  GasSettings s;
  s.mesh.origin = Vec3(-0.12, -0.12, 0.0);
  s.mesh.lengths = Vec3(0.24, 0.24, kH);
  s.mesh.cells = {12, 12, 20};
  s.geometry = Geometry({{Geometry::Op::Union, Primitive::cylinder(0, 0, 0.1, 0, kH), ""}});
  s.gas = {kRho, 1.8e-5, Vec3(0, 0, -kG)};
  s.boundaries = {{"zmin", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0},
                  {"walls", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0},
                  {"zmax", BoundaryType::PressureOutlet, Vec3::Zero(), kPout}};
  tightSolvers(s);
  return s;
}

GlobalFields runColumn(MPI_Comm comm) {
  GasSolver gas(columnSettings(), comm);
  const Mesh& m = gas.mesh();
  ScalarField alpha(m.nLocalCells()), beta(m.nLocalCells());
  for (int c = 0; c < m.nLocalCells(); ++c) {
    const Vec3& x = m.cellCentre(c);
    alpha[c] = 0.45 + 0.4 * std::pow(std::sin(30 * x[0] + 17 * x[1] + 11 * x[2]), 2);
    beta[c] = 1e5 * (1 - alpha[c]);
  }
  gas.setGasFraction(alpha);
  gas.setDragCoefficient(beta);
  gas.setDragSource(VectorField(m.nLocalCells(), Vec3::Zero()));
  for (int step = 0; step < 10; ++step) gas.advance(1e-3);
  return gather(gas);
}
}  // namespace

TEST(Hydrostatic, GasAtRestStaysAtRest) {
  const GlobalFields f = runColumn(MPI_COMM_WORLD);
  if (isRoot()) {
    double dp = 0, umax = 0;
    for (std::size_t i = 0; i < f.p.size(); ++i) {
      const double exact = kPout + kRho * kG * (kH - f.centre[i][2]);
      dp = std::max(dp, std::abs(f.p[i] - exact));
      umax = std::max(umax, Vec3(f.ux[i], f.uy[i], f.uz[i]).norm());
    }
    const double relDp = dp / (kRho * kG * kH);
    std::cout << "[measured] gas at rest: max |p - p_hydrostatic| / (rho g H) = " << relDp
              << " (|p - p_h| / p = " << dp / kPout << "), max |u| = " << umax << " m/s"
              << std::endl;
    EXPECT_LT(dp / kPout, 1e-14);
    EXPECT_LT(umax, 1e-14);
  }
  const double diff = rankAgreement(runColumn, f, kPout, 1.0);
  if (worldSize() > 1) {
    EXPECT_LT(diff, 1e-10);
  }
}
