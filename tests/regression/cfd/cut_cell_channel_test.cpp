// A plane channel at 30 degrees to x in the x-y plane, on cut cells (issue 31, verification "a channel
// whose walls are at 30 degrees to the axes"): unlike the duct (flow along z, uniform pressure), the flow
// and the pressure gradient here run along the slant, across the Cartesian faces, so the pressure
// equation's non-orthogonal correction enters. The channel (half-width a, one cell layer, free-slip z
// planes) enters through the box's xmin side, a velocity inlet along x over the face's open part (the
// channel's oblique section, 2a / cos 30 per unit depth: flow rate Q exact), and leaves through xmax, a
// pressure outlet. The flow turns and develops near the oblique ends; away from them (|s| < 0.4 m, s along
// the channel; the ends begin at |s| = 1.04 m) it is plane Poiseuille flow (White, Viscous Fluid Flow,
// eq. 3-40):  u_s(eta) = 3 Q / (4 a) (1 - eta^2 / a^2),  u_eta = 0,  dp/ds = -3 mu Q / (2 a^3),
// eta across the channel. What leaves through xmax must be Q (mass balance). Measured at 20, 40 and 80
// cells across the 2 m box (4, 8 and 16 across the channel; cfd/README.md, "Cut cells in the solver").
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <memory>

#include "cfd/geometry/solid_surface.hpp"
#include "tests/support/cut_cell_test_surfaces.hpp"
#include "tests/regression/cfd/gas_case.hpp"

using namespace parcelflow::cfd;
using namespace parcelflow::cfd::testing;

namespace {
constexpr double kRho = 1.0, kMu = 0.1, kA = 0.2, kDepth = 0.1, kInletVelocity = 0.01, kMiddle = 0.4;
const double kAngle = M_PI / 6;
// The inlet's open part of x = -1 is the channel's section cut at 30 degrees: 2a / cos 30 deep per depth.
const double kFlowRate = kInletVelocity * 2 * kA / std::cos(kAngle);
const Vec3 kAlong(std::cos(kAngle), std::sin(kAngle), 0), kAcross(-std::sin(kAngle), std::cos(kAngle), 0);

GasSettings channelSettings(int n) {
  GasSettings s;
  // x in [-1, 1], y in [-0.85, 0.85]: the channel's walls leave through x = +-1 at |y| < 0.81.
  s.mesh.origin = Vec3(-1.0, -0.85, 0.0);
  s.mesh.lengths = Vec3(2.0, 1.7, kDepth);
  s.mesh.cells = {n, n * 17 / 20, 1};
  s.mesh.walls = WallRepresentation::CutCells;
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(kAngle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  auto channel = test::transformed(test::boxSurface(Vec3(-1.5, -kA, -kDepth), Vec3(1.5, kA, 2 * kDepth)), turn,
                                   Vec3::Zero());
  s.geometry = Geometry(
      {{Geometry::Op::Union, Primitive::surface(std::make_shared<SolidSurface>(std::move(channel))), ""}});
  s.gas = {kRho, kMu, Vec3::Zero()};
  s.boundaries = {{"xmin", BoundaryType::VelocityInlet, Vec3(kInletVelocity, 0, 0), 0.0},
                  {"xmax", BoundaryType::PressureOutlet, Vec3::Zero(), 0.0},
                  {"zmin", BoundaryType::FreeSlipWall, Vec3::Zero(), 0.0},
                  {"zmax", BoundaryType::FreeSlipWall, Vec3::Zero(), 0.0},
                  {"walls", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0}};
  tightSolvers(s);
  return s;
}

struct ChannelRun {
  GlobalFields fields;
  double flowRate = 0;        // per unit depth, out through xmax
  double massBalance = 0;     // (in through xmin - out through xmax) / out
  double velocityError = 0;   // volume-weighted L2 of u - exact over the middle cells, over the exact u_max
  double gradientError = 0;   // least-squares dp/ds of the middle cells / exact - 1
};

ChannelRun runChannel(int n, MPI_Comm comm) {
  GasSolver gas(channelSettings(n), comm);
  // dt = 0.5 s against the viscous decay across the channel, 4 a^2 / (pi^2 nu) = 0.16 s. The cells along
  // the walls settle more slowly (at 80 cells the error was 1.841e-3 after 60 steps, 1.729e-3 after 300 and
  // 1.728e-3 after 600; 1.731e-3 after 600 steps of 0.05 s: the Rhie-Chow fluxes depend on dt by 2e-3 of
  // the error), so 300 steps.
  for (int step = 0; step < 300; ++step) gas.advance(0.5);
  ChannelRun r;
  r.flowRate = gas.patchOutflow("xmax") / kDepth;
  r.massBalance = (-gas.patchOutflow("xmin") / kDepth - r.flowRate) / r.flowRate;
  const double uMax = 3 * kFlowRate / (4 * kA);
  const Mesh& m = gas.mesh();
  double err2 = 0, volume = 0, n1 = 0, sS = 0, sP = 0, sSS = 0, sSP = 0;
  for (int c = 0; c < m.nOwnedCells(); ++c) {
    const Vec3& x = m.cellCentre(c);
    const double s = x.dot(kAlong), eta = x.dot(kAcross), V = m.cellVolume(c);
    if (std::abs(s) > kMiddle) continue;
    const Vec3 exact = uMax * (1 - eta * eta / (kA * kA)) * kAlong;
    err2 += V * (gas.velocity()[c] - exact).squaredNorm();
    volume += V;
    const double p = gas.pressure()[c];
    n1 += 1;
    sS += s;
    sP += p;
    sSS += s * s;
    sSP += s * p;
  }
  r.velocityError = std::sqrt(m.sum(err2) / m.sum(volume)) / uMax;
  n1 = m.sum(n1), sS = m.sum(sS), sP = m.sum(sP), sSS = m.sum(sSS), sSP = m.sum(sSP);
  const double slope = (n1 * sSP - sS * sP) / (n1 * sSS - sS * sS);
  r.gradientError = slope / (-3 * kMu * kFlowRate / (2 * kA * kA * kA)) - 1;
  r.fields = gather(gas);
  return r;
}
}  // namespace

TEST(CutCellChannel, SlantedPressureDrivenFlowSecondOrderAndMassBalance) {
  const int n[3] = {20, 40, 80};
  ChannelRun r[3];
  for (int i = 0; i < 3; ++i) r[i] = runChannel(n[i], MPI_COMM_WORLD);
  double order[3] = {0, 0, 0};
  for (int i = 1; i < 3; ++i) order[i] = std::log2(r[i - 1].velocityError / r[i].velocityError);
  if (isRoot()) {
    std::printf("[measured] cut-cell channel at 30 degrees in the x-y plane (2a = %.1f m), cells across 2 m | "
                "L2 velocity error / u_max (|s| < %.1f m) | observed order | dp/ds / exact - 1 | flow rate "
                "[m2/s] | (in - out) / out\n",
                2 * kA, kMiddle);
    for (int i = 0; i < 3; ++i) {
      char orderText[16] = "   -";
      if (i > 0) std::snprintf(orderText, sizeof orderText, "%4.2f", order[i]);
      std::printf("[measured]   %2d | %.3e | %s | %+.3e | %.6e | %+.1e\n", n[i], r[i].velocityError, orderText,
                  r[i].gradientError, r[i].flowRate, r[i].massBalance);
    }
  }
  for (const auto& run : r) {
    EXPECT_LT(std::abs(run.massBalance), 1e-9);
    EXPECT_NEAR(run.flowRate / kFlowRate, 1.0, 1e-9);  // the cut inlet face's open area
  }
  EXPECT_GT(order[1], 1.5);
  EXPECT_GT(order[2], 1.5);
  EXPECT_LT(std::abs(r[2].gradientError), 0.01);
  const double diff = rankAgreement([&](MPI_Comm c) { return runChannel(40, c).fields; }, r[1].fields,
                                    1e-3, 3 * kFlowRate / (4 * kA));
  if (worldSize() > 1) {
    EXPECT_LT(diff, 1e-10);
  }
}
