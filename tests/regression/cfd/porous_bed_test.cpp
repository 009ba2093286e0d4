// Verification 2: frozen porous bed. Uniform a_g = 0.45, u_s = 0 and beta from the Ergun law at the
// imposed superficial velocity U (air, d_p = 0.5 mm). With interstitial u = U / a_g the momentum
// balance a_g dp/dz = -beta u + a_g rho g gives |dp/dz| = beta U / a_g^2 + rho |g|.
#include <gtest/gtest.h>

#include <iostream>

#include "tests/regression/cfd/gas_case.hpp"

using namespace parcelflow::cfd;
using namespace parcelflow::cfd::testing;

namespace {
constexpr double kRho = 1.2, kMu = 1.8e-5, kG = 9.81, kAlpha = 0.45, kDp = 0.5e-3, kU = 0.05;

double ergunBeta() {
  const double as = 1.0 - kAlpha, slip = kU / kAlpha;
  return 150.0 * as * as * kMu / (kAlpha * kDp * kDp) + 1.75 * as * kRho * slip / kDp;
}

GasSettings bedSettings() {
  GasSettings s;
  s.mesh.lengths = Vec3(0.04, 0.04, 0.2);
  s.mesh.cells = {4, 4, 40};
  s.gas = {kRho, kMu, Vec3(0, 0, -kG)};
  s.boundaries = columnBoundaries(kU);
  tightSolvers(s);
  return s;
}

GlobalFields runBed(MPI_Comm comm) {
  GasSolver gas(bedSettings(), comm);
  const int n = gas.mesh().nLocalCells();
  gas.setGasFraction(ScalarField(n, kAlpha));
  gas.setDragCoefficient(ScalarField(n, ergunBeta()));
  gas.setDragSource(VectorField(n, Vec3::Zero()));
  // Drag relaxes the gas in rho a / beta ~ 1e-4 s; 40 steps of 5 ms reach the steady state.
  for (int step = 0; step < 40; ++step) gas.advance(5e-3);
  return gather(gas);
}
}  // namespace

TEST(PorousBed, PressureDropMatchesErgunBalance) {
  const GlobalFields f = runBed(MPI_COMM_WORLD);
  if (isRoot()) {
    // Pressure drop per length between the lowest and highest cell layers (averaged over x, y).
    double zLo = 1e30, zHi = -1e30, pLo = 0, pHi = 0;
    int nLo = 0, nHi = 0;
    for (const auto& x : f.centre) {
      zLo = std::min(zLo, x[2]);
      zHi = std::max(zHi, x[2]);
    }
    for (std::size_t i = 0; i < f.p.size(); ++i) {
      if (f.centre[i][2] == zLo) pLo += f.p[i], ++nLo;
      if (f.centre[i][2] == zHi) pHi += f.p[i], ++nHi;
    }
    const double measured = (pLo / nLo - pHi / nHi) / (zHi - zLo);
    const double analytic = ergunBeta() * kU / (kAlpha * kAlpha) + kRho * kG;
    const double relErr = std::abs(measured - analytic) / analytic;
    std::cout << "[measured] porous bed: beta = " << ergunBeta() << " kg/(m^3 s), dp/L = " << measured
              << " Pa/m, analytic " << analytic << " Pa/m, relative error " << relErr << std::endl;
    EXPECT_LT(relErr, 0.005);
  }
  const double diff = rankAgreement(runBed, f, 1e5, 0.0);
  if (worldSize() > 1) {
    EXPECT_LT(diff, 1e-10);
  }
}
