// Contact conduction of parcels (fix heat/gran/conduction under fix parcel/heat, 1 and 2 ranks): a simple
// cubic lattice of spheres heated from a wall is a 1-D chain of layers, which the test integrates itself
// with LIGGGHTS' contact conductances (2 k sqrt(A), A from the overlap) and its explicit Euler step. The
// lattice of particles (l = 1) and of parcels (l = 2, 3: diameter l d, the same overlap per diameter as
// `scaling linear` keeps) follow their chains to round-off: a parcel contact has l times a particle
// contact's conductance, which keeps the bed's effective conductivity. The parcel beds' mean temperature
// histories against the particles' measure what coarse graining costs (lumping l layers into one, and the
// wall contact): within 5 % of T_w - T0.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "liggghts_plugins/fix_parcel_heat.hpp"
#include "tests/regression/plugins/liggghts_session.h"

using namespace parcelflow::plugins;
using namespace parcelflow::plugins::testing;

namespace {

const std::string kDir = PARCEL_TEST_DIR;
constexpr double kPi = 3.14159265358979323846;
constexpr double kParticle = 1e-3, kEps = 0.01, kEpsWall = 0.01, kDt = 0.2, kT0 = 300.0, kTw = 400.0;
constexpr int kLayers = 24, kSteps = 8000, kEvery = 400;
constexpr double kConductivity = 1.0, kDensity = 2500.0, kHeatCapacity = 840.0;

// The bed's mean temperature every kEvery steps, as the chain of layers gives it for spheres of l d.
std::vector<double> chain(int l)
{
  const double D = l * kParticle, R = 0.5 * D, delta = kEps * D, deltaWall = kEpsWall * D;
  const int n = kLayers / l;
  const double mc = kDensity * kPi * D * D * D / 6.0 * kHeatCapacity;
  const double contact = 2.0 * kConductivity * std::sqrt(kPi * (R * delta - 0.25 * delta * delta));
  const double wall = 2.0 * kConductivity * std::sqrt(kPi * (R * R - (R - deltaWall) * (R - deltaWall)));
  std::vector<double> T(n, kT0), q(n), mean;
  for (int step = 1; step <= kSteps; ++step) {
    std::fill(q.begin(), q.end(), 0.0);
    q[0] += wall * (kTw - T[0]);
    for (int i = 0; i + 1 < n; ++i) {
      const double f = contact * (T[i + 1] - T[i]);
      q[i] += f;
      q[i + 1] -= f;
    }
    for (int i = 0; i < n; ++i) T[i] += kDt * q[i] / mc;
    if (step % kEvery == 0) {
      double sum = 0.0;
      for (double t : T) sum += t;
      mean.push_back(sum / n);
    }
  }
  return mean;
}

std::vector<double> lattice(int l, long& atoms)
{
  Session s("none");
  const double D = l * kParticle;
  s.cmd("variable D equal " + std::to_string(D));
  s.cmd("variable eps equal " + std::to_string(kEps));
  s.cmd("variable epsw equal " + std::to_string(kEpsWall));
  s.cmd("variable nx equal " + std::to_string(kLayers / l));
  s.cmd("variable dt equal " + std::to_string(kDt));
  s.cmd("variable skin equal " + std::to_string(0.2 * D));
  s.file(kDir + "/lattice.in");
  s.cmd("run 0");
  auto* fix = s.fix<FixParcelHeat>("heat");
  double mc = 0.0;
  for (int i = 0; i < s.lmp()->atom->nlocal; ++i) mc += fix->heat_capacity(i);
  mc = sum_all(mc);
  atoms = sum_all(static_cast<long>(s.lmp()->atom->nlocal));
  std::vector<double> mean;
  for (int step = kEvery; step <= kSteps; step += kEvery) {
    s.cmd("run " + std::to_string(kEvery) + " pre no post no");
    mean.push_back(fix->compute_scalar() / mc);
  }
  return mean;
}

}  // namespace

TEST(ConductionScaling, LatticeBedsFollowTheirChainsAndParcelsKeepTheHeating)
{
  const std::vector<double> fine = chain(1);
  for (int l : {1, 2, 3}) {
    long atoms = 0;
    const std::vector<double> bed = lattice(l, atoms), model = chain(l);
    ASSERT_EQ(bed.size(), model.size());
    double vs_chain = 0.0, vs_fine = 0.0;
    for (std::size_t k = 0; k < bed.size(); ++k) {
      vs_chain = std::max(vs_chain, std::fabs(bed[k] - model[k]));
      vs_fine = std::max(vs_fine, std::fabs(bed[k] - fine[k]) / (kTw - kT0));
    }
    PF_PRINT("[ conduction ] l = %d (%ld spheres, %d layers): mean T after %.0f s %.4f K (particles' %.4f K); max "
             "|lattice - chain| = %.1e K; max |mean T - particles'| = %.4f of T_w - T0\n",
             l, atoms, kLayers / l, kSteps * kDt, bed.back(), fine.back(), vs_chain, vs_fine);
    EXPECT_EQ(atoms, 4L * (kLayers / l));
    EXPECT_LT(vs_chain, 1e-9);
    EXPECT_LT(vs_fine, 0.05);
  }
}
