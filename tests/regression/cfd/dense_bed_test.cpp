// Verification 6: dense frozen bed with strong drag under a freeboard. The lower half of the column
// holds a_g = 0.4 with an Ergun beta (~4e4 kg/(m^3 s)), the upper half is free gas. A collocated
// scheme without the drag in its Rhie-Chow diagonal decouples odd and even cells here; ours must give
// a linear pressure in the bed: the largest second difference of layer-averaged p along z is measured
// relative to the bed pressure drop.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>

#include "tests/regression/cfd/gas_case.hpp"

using namespace parcelflow::cfd;
using namespace parcelflow::cfd::testing;

namespace {
constexpr double kRho = 1.2, kMu = 1.8e-5, kAlpha = 0.4, kDp = 0.3e-3, kU = 0.3, kL = 0.3;

double ergunBeta() {
  const double as = 1.0 - kAlpha, slip = kU / kAlpha;
  return 150.0 * as * as * kMu / (kAlpha * kDp * kDp) + 1.75 * as * kRho * slip / kDp;
}

GasSettings columnSettings() {
  GasSettings s;
  s.mesh.lengths = Vec3(0.03, 0.03, kL);
  s.mesh.cells = {3, 3, 60};
  s.gas = {kRho, kMu, Vec3(0, 0, -9.81)};
  s.boundaries = columnBoundaries(kU);
  tightSolvers(s);
  return s;
}

GlobalFields runBed(MPI_Comm comm) {
  GasSolver gas(columnSettings(), comm);
  const Mesh& m = gas.mesh();
  ScalarField alpha(m.nLocalCells()), beta(m.nLocalCells());
  for (int c = 0; c < m.nLocalCells(); ++c) {
    const bool inBed = m.cellCentre(c)[2] < 0.5 * kL;
    alpha[c] = inBed ? kAlpha : 1.0;
    beta[c] = inBed ? ergunBeta() : 0.0;
  }
  gas.setGasFraction(alpha);
  gas.setDragCoefficient(beta);
  gas.setDragSource(VectorField(m.nLocalCells(), Vec3::Zero()));
  for (int step = 0; step < 100; ++step) gas.advance(5e-3);
  return gather(gas);
}
}  // namespace

TEST(DenseBed, NoOddEvenPressureOscillation) {
  const GlobalFields f = runBed(MPI_COMM_WORLD);
  if (isRoot()) {
    std::map<double, std::pair<double, int>> layers;  // z -> (sum p, count)
    for (std::size_t i = 0; i < f.p.size(); ++i) {
      auto& l = layers[f.centre[i][2]];
      l.first += f.p[i];
      ++l.second;
    }
    std::vector<double> z, p;
    for (const auto& [zk, l] : layers) {
      z.push_back(zk);
      p.push_back(l.first / l.second);
    }
    int kSurface = 0;
    while (z[kSurface + 1] < 0.5 * kL) ++kSurface;  // last bed layer
    const double bedDp = p[0] - p[kSurface];
    // Second differences in the bed, in the freeboard, and within 3 cells of the bed surface, where
    // the jump of u (0.75 -> 0.3 m/s) legitimately bends p through the convective momentum flux.
    double bed = 0, freeboard = 0, surface = 0;
    for (int k = 1; k + 1 < static_cast<int>(p.size()); ++k) {
      const double second = std::abs(p[k + 1] - 2 * p[k] + p[k - 1]) / bedDp;
      double& slot = k <= kSurface - 3 ? bed : (k >= kSurface + 4 ? freeboard : surface);
      slot = std::max(slot, second);
    }
    std::cout << "[measured] dense bed (beta = " << ergunBeta() << " kg/(m^3 s)): bed dp = " << bedDp
              << " Pa (per cell " << bedDp / kSurface << " Pa); max |p[k+1] - 2 p[k] + p[k-1]| / bed dp:"
              << " bed " << bed << ", freeboard " << freeboard << ", within 3 cells of the surface "
              << surface << std::endl;
    // An odd-even mode would be of the order of the per-cell drop, i.e. ~1/30 of the bed dp. At the
    // surface the slope change itself gives one second difference of (per-cell drop) / bed dp.
    EXPECT_LT(bed, 1e-6);
    EXPECT_LT(freeboard, 1e-5);
    EXPECT_LT(surface, 1.05 / kSurface);
  }
  const double diff = rankAgreement(runBed, f, 1e5, 0.0);
  if (worldSize() > 1) {
    EXPECT_LT(diff, 1e-10);
  }
}
