// parcel/implicit_drag (on 1 and 2 ranks): one parcel with constant kappa and u_f under gravity relaxes to
// u_f + M g / kappa exactly as the discrete recursion of the implicit half steps predicts, also when
// dt kappa / M = 100 (an explicit update would be unstable beyond 2); with kappa = 0 it is nve/sphere.
#include <gtest/gtest.h>

#include <cmath>

#include "liggghts_plugins/fix_parcel_implicit_drag.h"
#include "tests/regression/plugins/liggghts_session.h"
#include "update.h"

using namespace parcelflow::plugins;
using namespace parcelflow::plugins::testing;

namespace {

const std::string kDir = PARCEL_TEST_DIR;

// Runs `steps` steps with the given dt*kappa/M; returns max |v - v_recursion| over the run (checked
// every chunk) and the final |v - (u_f + M g/kappa)|.
void relax(double dt_kappa_over_m, int steps, double& max_err, double& final_dev, double& v_star_z)
{
  Session s("none");
  s.file(kDir + "/drag.in");
  s.cmd("run 0");
  auto* fix = s.fix<FixParcelImplicitDrag>("drag");
  ASSERT_NE(fix, nullptr);
  LAMMPS_NS::Atom* atom = s.lmp()->atom;
  const double dt = s.lmp()->update->dt, g[3] = {0, 0, -9.81}, uf[3] = {0.3, -0.1, 0.5};
  double M = 0, v[3] = {0, 0, 0};
  if (atom->nlocal == 1) {
    M = atom->rmass[0];
    for (int k = 0; k < 3; ++k) v[k] = atom->v[0][k];
  }
  M = sum_all(M);
  for (int k = 0; k < 3; ++k) v[k] = sum_all(v[k]);
  const double kappa = dt_kappa_over_m * M / dt;
  if (atom->nlocal == 1) {
    fix->peratom()[0][FixParcelImplicitDrag::KAPPA] = kappa;
    for (int k = 0; k < 3; ++k) fix->peratom()[0][FixParcelImplicitDrag::UFX + k] = uf[k];
  }
  // recursion of one half step h: v <- (v + h g + h c u)/(1 + h c), c = kappa/M
  const double h = 0.5 * dt, c = kappa / M;
  max_err = 0;
  const int chunk = 10;
  for (int n = 0; n < steps; n += chunk) {
    s.cmd("run " + std::to_string(chunk) + " pre no post no");
    for (int m = 0; m < 2 * chunk; ++m)
      for (int k = 0; k < 3; ++k) v[k] = (v[k] + h * g[k] + h * c * uf[k]) / (1.0 + h * c);
    double err = 0;
    for (int i = 0; i < atom->nlocal; ++i)
      for (int k = 0; k < 3; ++k) err = std::max(err, std::fabs(atom->v[i][k] - v[k]));
    max_err = std::max(max_err, max_all(err));
  }
  final_dev = 0;
  for (int i = 0; i < atom->nlocal; ++i)
    for (int k = 0; k < 3; ++k)
      final_dev = std::max(final_dev, std::fabs(atom->v[i][k] - (c > 0 ? uf[k] + g[k] / c : v[k])));
  final_dev = max_all(final_dev);
  v_star_z = c > 0 ? uf[2] + g[2] / c : 0.0;
}

}  // namespace

TEST(ParcelImplicitDrag, RelaxesAsTheDiscreteRecursionPredicts)
{
  for (double a : {0.1, 2.0, 100.0}) {
    double err = 0, dev = 0, vz = 0;
    relax(a, 400, err, dev, vz);
    PF_PRINT("[ drag ] dt kappa/M = %6.1f: max |v - v_recursion| over 400 steps = %.2e m/s, |v - (u_f + M g/kappa)| "
             "after 400 steps = %.2e m/s (v*_z = %.6f m/s)\n", a, err, dev, vz);
    EXPECT_LT(err, 1e-12);
    if (a >= 2.0) {
      EXPECT_LT(dev, 1e-12);  // converged; at 0.1 the recursion itself is still relaxing
    }
  }
}

TEST(ParcelImplicitDrag, ZeroKappaIsNveSphere)
{
  double err = 0, dev = 0, vz = 0;
  relax(0.0, 200, err, dev, vz);
  PF_PRINT("[ drag ] kappa = 0: max |v - (v0 + g t)| over 200 steps = %.2e m/s\n", err);
  EXPECT_LT(err, 1e-12);
}
