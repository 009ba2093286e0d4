// fix parcel/heat inside LIGGGHTS (1 and 2 ranks): a particle and a parcel of np 8 of the same particles
// in gas of a fixed temperature, with Gunn's conductance, against the lumped solution
// T_g + (T0 - T_g) exp(-t H/(M c)); a DEM step far above the response time; the heat received;
// a restart round trip; LIGGGHTS' contact conduction in the same run.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "liggghts_plugins/fix_parcel_heat.hpp"
#include "tests/regression/plugins/liggghts_session.h"
#include "liggghts_plugins/parcel_heat_step.hpp"
#include "coupling/heat/parcel_heat_transfer.hpp"
#include "update.h"

using namespace parcelflow::plugins;
using namespace parcelflow::plugins::testing;
namespace pc = parcelflow::coupling;

namespace {

const std::string kDir = PARCEL_TEST_DIR;
constexpr double kTg = 600.0, kT0 = 300.0, kC = 840.0;

// Gunn's H for a particle (np 1, atom 1) and a parcel of np 8 (atom 2) of real diameter dp, at a_g 0.45
// and slip 0.3 m/s in air, through the coupling layer's batch loop.
std::array<double, 2> gunnConductance(double dp)
{
  const std::vector<double> a(2, 0.45), slip(2, 0.3), d(2, dp), np{1.0, 8.0};
  pc::ParcelHeatBatch b;
  b.size = 2;
  b.alphaG = a.data();
  b.slip = slip.data();
  b.dp = d.data();
  b.np = np.data();
  b.gas = {1.2, 1.8e-5, 0.026, 1005.0};
  std::array<double, 2> h{};
  pc::computeParcelConductance(pc::makeNusseltCorrelation("Gunn"), b, {0.3}, h.data());
  return h;
}

void setGas(Session& s, const std::array<double, 2>& h)
{
  auto* fix = s.fix<FixParcelHeat>("heat");
  ASSERT_NE(fix, nullptr);
  LAMMPS_NS::Atom* atom = s.lmp()->atom;
  for (int i = 0; i < atom->nlocal; ++i) {
    fix->peratom()[i][FixParcelHeat::GAS_TEMPERATURE] = kTg;
    fix->peratom()[i][FixParcelHeat::CONDUCTANCE] = h[atom->tag[i] - 1];
  }
}

struct Atoms {
  std::map<int, std::array<double, 4>> v;  // tag -> T, M, heat received, M c
};

Atoms gather(Session& s)
{
  auto* fix = s.fix<FixParcelHeat>("heat");
  LAMMPS_NS::LAMMPS* lmp = s.lmp();
  return {gather_by_tag<4>(lmp, [&](int i) {
    return std::array<double, 4>{fix->temperature()[i], lmp->atom->rmass[i],
                                 fix->peratom()[i][FixParcelHeat::HEAT_RECEIVED], fix->heat_capacity(i)};
  })};
}

void start(Session& s, double dp, double dt)
{
  s.cmd("variable dp equal " + std::to_string(dp));
  s.cmd("variable dt equal " + std::to_string(dt));
  s.cmd("variable dir string " + kDir);
  s.file(kDir + "/lumped.in");
  s.cmd("run 0");
}

}  // namespace

TEST(ParcelHeat, ParticleAndParcelFollowTheLumpedSolution)
{
  // d_p = 100 um glass in air; DEM step 10 us, far below M c / H
  const double dp = 1e-4, dt = 1e-5;
  Session s("none");
  start(s, dp, dt);
  const auto h = gunnConductance(dp);
  setGas(s, h);
  const Atoms a0 = gather(s);
  const double tau1 = a0.v.at(1)[3] / h[0], tau8 = a0.v.at(2)[3] / h[1];
  EXPECT_NEAR(a0.v.at(2)[1] / a0.v.at(1)[1], 8.0, 1e-12);  // the parcel holds 8 particles' mass
  EXPECT_NEAR(tau8 / tau1, 1.0, 1e-12);
  double err = 0.0, parcel_vs_particle = 0.0, received = 0.0;
  const int chunk = 100, steps = 6000;
  for (int n = chunk; n <= steps; n += chunk) {
    s.cmd("run " + std::to_string(chunk) + " pre no post no");
    const Atoms a = gather(s);
    const double t = n * dt;
    for (int tag : {1, 2}) {
      const double tau = tag == 1 ? tau1 : tau8;
      const double exact = kTg + (kT0 - kTg) * std::exp(-t / tau);
      err = std::max(err, std::fabs(a.v.at(tag)[0] - exact) / (kTg - kT0));
      const double mc = a.v.at(tag)[3];
      received = std::max(received, std::fabs(a.v.at(tag)[2] - mc * (a.v.at(tag)[0] - kT0)) / (mc * (kTg - kT0)));
    }
    parcel_vs_particle = std::max(parcel_vs_particle, std::fabs(a.v.at(2)[0] - a.v.at(1)[0]));
  }
  const long received_atoms = sum_all(s.fix<FixParcelHeat>("heat")->atoms_received());
  PF_PRINT("[ heat ] %d rank(s): %ld atoms changed ranks during the run\n", nranks(), received_atoms);
  if (nranks() > 1) {
    EXPECT_GT(received_atoms, 0);
  }
  PF_PRINT("[ heat ] d_p 100 um, Gunn H = %.6e W/K (np 1), %.6e (np 8), M c/H = %.4f ms, dt/tau = %.2e, t = %.1f tau: "
           "max |T - T_lumped| = %.3e of T_g - T0; max |T_parcel - T_particle| = %.2e K; heat received vs M c dT: %.1e\n",
           h[0], h[1], tau1 * 1e3, dt / tau1, steps * dt / tau1, err, parcel_vs_particle, received);
  EXPECT_LT(err, 5e-3);
  EXPECT_LT(parcel_vs_particle, 1e-9);
  EXPECT_LT(received, 1e-10);
}

TEST(ParcelHeat, StepFarAboveTheResponseTimeNeitherOvershootsNorDiverges)
{
  // d_p = 10 um: M c / H = 0.27 ms, DEM step 10 ms
  const double dp = 1e-5, dt = 1e-2;
  Session s("none");
  start(s, dp, dt);
  const auto h = gunnConductance(dp);
  setGas(s, h);
  const double mc = gather(s).v.at(1)[3];
  double recursion = kT0, previous = kT0, dev = 0.0, parcel_vs_particle = 0.0;
  bool monotone = true;
  for (int n = 1; n <= 20; ++n) {
    s.cmd("run 1 pre no post no");
    recursion = implicit_heat_step(mc, recursion, dt, h[0], kTg, 0.0);
    const Atoms a = gather(s);
    const double T = a.v.at(1)[0];
    monotone = monotone && T >= previous && T <= kTg;
    previous = T;
    dev = std::max(dev, std::fabs(T - recursion));
    parcel_vs_particle = std::max(parcel_vs_particle, std::fabs(a.v.at(2)[0] - T));
  }
  PF_PRINT("[ heat ] d_p 10 um, dt H/(M c) = %.2f: after 1 step T = %.4f K (T_g = %.0f), after 20 steps T_g - T = %.2e K; "
           "monotone %s; max |T - implicit Euler| = %.1e K; parcel vs particle %.1e K\n",
           dt * h[0] / mc, implicit_heat_step(mc, kT0, dt, h[0], kTg, 0.0), kTg, kTg - previous,
           monotone ? "yes" : "NO", dev, parcel_vs_particle);
  EXPECT_GT(dt * h[0] / mc, 30.0);  // an explicit step would oscillate and grow beyond 2
  EXPECT_TRUE(monotone);
  EXPECT_LT(dev, 1e-9);
  EXPECT_LT(kTg - previous, 1e-9 * kTg);
  EXPECT_LT(parcel_vs_particle, 1e-9);
}

TEST(ParcelHeat, HeldSourceAddsExactlyItsHeat)
{
  // S alone (H = 0): M c dT = dt S every step, and the heat received is n dt S; with H as well the parcel
  // settles at T_g + S/H.
  const double dp = 1e-4, dt = 1e-5, S = 2e-4;
  Session s("none");
  start(s, dp, dt);
  auto* fix = s.fix<FixParcelHeat>("heat");
  LAMMPS_NS::Atom* atom = s.lmp()->atom;
  const auto h = gunnConductance(dp);
  for (int i = 0; i < atom->nlocal; ++i) {
    fix->peratom()[i][FixParcelHeat::SOURCE] = S;
    fix->peratom()[i][FixParcelHeat::CONDUCTANCE] = atom->tag[i] == 2 ? h[1] : 0.0;
    fix->peratom()[i][FixParcelHeat::GAS_TEMPERATURE] = kTg;
  }
  const double mc = gather(s).v.at(1)[3];
  s.cmd("run 1000 pre no post no");
  const Atoms a = gather(s);
  const double expected = kT0 + 1000 * dt * S / mc;
  s.cmd("velocity all set 0 0 0");  // at rest: no neighbour-list builds at the long step
  s.cmd("timestep 1e-3");           // 45 response times in 1000 steps: settled
  s.cmd("run 1000");
  const double settled = gather(s).v.at(2)[0];
  PF_PRINT("[ heat ] held source %.1e W, 1000 steps: T = %.9f K (expected %.9f), heat received %.6e J (expected %.6e); "
           "with H: %.6f K (T_g + S/H = %.6f K)\n", S, a.v.at(1)[0], expected, a.v.at(1)[2], 1000 * dt * S, settled,
           kTg + S / h[1]);
  EXPECT_NEAR(a.v.at(1)[0], expected, 1e-9);
  EXPECT_NEAR(a.v.at(1)[2], 1000 * dt * S, 1e-15);
  EXPECT_NEAR(settled, kTg + S / h[1], 1e-6);
}

TEST(ParcelHeat, RestartContinuesBitForBit)
{
  const double dp = 1e-4, dt = 1e-5;
  const std::string dir = scratch_dir("parcel_heat_restart");
  std::map<int, std::array<double, 4>> straight, restarted;
  {
    Session s("none");
    start(s, dp, dt);
    setGas(s, gunnConductance(dp));
    s.cmd("run 300 pre no post no");
    s.cmd("write_restart " + dir + "/heat.restart");
    s.cmd("run 300");
    straight = gather(s).v;
  }
  {
    Session s("none");
    s.cmd("variable dt equal " + std::to_string(dt));
    s.cmd("variable F string " + dir + "/heat.restart");
    s.file(kDir + "/restart_continue.in");
    s.cmd("run 300");
    restarted = gather(s).v;
  }
  ASSERT_EQ(straight.size(), 2u);
  ASSERT_EQ(restarted.size(), 2u);
  double diff = 0.0;
  for (int tag : {1, 2})
    for (int c = 0; c < 4; ++c) diff = std::max(diff, std::fabs(straight.at(tag)[c] - restarted.at(tag)[c]));
  PF_PRINT("[ heat ] restart after 300 steps, 300 more: T = %.12f K / %.12f K, largest difference %.1e\n",
           straight.at(1)[0], restarted.at(1)[0], diff);
  EXPECT_EQ(diff, 0.0);
  EXPECT_GT(straight.at(1)[0], 350.0);  // it did heat, after the restart too
  remove_scratch_dir(dir);
}

TEST(ParcelHeat, WithLiggghtsContactConductionEnergyIsConserved)
{
  Session s("none");
  s.cmd("variable dir string " + kDir);
  s.file(kDir + "/conduction.in");
  s.cmd("run 0");
  auto* fix = s.fix<FixParcelHeat>("heat");
  ASSERT_NE(fix, nullptr);
  const double e0 = fix->compute_scalar();
  const auto before = gather(s).v;
  s.cmd("run 2000");
  const double e1 = fix->compute_scalar();
  const auto after = gather(s).v;
  const double dT1 = after.at(1)[0] - before.at(1)[0], dT2 = after.at(2)[0] - before.at(2)[0];
  PF_PRINT("[ heat ] contact conduction 2000 steps: T = %.6f K / %.6f K (from 300 / 400), heat content %.12e -> %.12e J "
           "(relative change %.1e)\n", after.at(1)[0], after.at(2)[0], e0, e1, std::fabs(e1 - e0) / e0);
  EXPECT_GT(dT1, 1e-3);  // heat flowed from the hot to the cold sphere
  EXPECT_LT(dT2, -1e-3);
  EXPECT_NEAR(dT1, -dT2, 1e-9);
  EXPECT_LT(std::fabs(e1 - e0) / e0, 1e-13);
}
