// fix parcel/implicit_drag: one parcel with constant kappa, gas velocity and gravity.
//  - its velocity follows the exact exponential relaxation v(t) = v_t + (v0 - v_t) exp(-kappa t / m),
//    v_t = u_f + m g / kappa, with the first-order error the scheme predicts;
//  - it reaches the steady state v_t exactly;
//  - it stays stable and monotone for kappa dt / m = 100 (a fine particle in a coarse DEM step).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "atom.h"
#include "liggghts_plugins/fix_parcel_implicit_drag.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "liggghts_plugins/register_styles.h"

namespace {

struct SingleParcel {
  LAMMPS_NS::LAMMPS* lmp;
  parcelflow::plugins::FixParcelImplicitDrag* fix;
  double mass;

  explicit SingleParcel(double dt) {
    std::string dts = std::to_string(dt);
    const char* args[] = {"test", "-screen", "none", "-log", "none", "-var", "dt", dts.c_str(), nullptr};
    lmp = new LAMMPS_NS::LAMMPS(8, const_cast<char**>(args), MPI_COMM_WORLD);
    parcelflow::plugins::register_styles(lmp);
    lmp->input->file(SOURCE_DIR "/single_parcel.in");
    fix = dynamic_cast<parcelflow::plugins::FixParcelImplicitDrag*>(lmp->modify->fix[lmp->modify->find_fix("integrate")]);
    mass = lmp->atom->rmass[0];
  }
  ~SingleParcel() { delete lmp; }

  void set(double kappa, double uz) {
    double* d = fix->peratom()[0];
    d[fix->KAPPA] = kappa;
    d[fix->UFX] = d[fix->UFY] = 0.0;
    d[fix->UFZ] = uz;
  }
  double vz() const { return lmp->atom->v[0][2]; }
  void steps(int n) { lmp->input->one(("run " + std::to_string(n) + " pre no post no").c_str()); }
};

constexpr double g = 9.81;

}  // namespace

// Largest deviation from the exact exponential relaxation over 10 relaxation times, relative to |v_t|.
double relaxationError(double x /* kappa dt / m */) {
  const double dt = 1e-5;
  SingleParcel p(dt);
  const double kappa = x * p.mass / dt;
  const double uz = 0.5;
  p.set(kappa, uz);
  const double v_terminal = uz - p.mass * g / kappa;
  const int steps_per_chunk = std::max(1, static_cast<int>(std::lround(0.05 / x)));
  double worst = 0.0;
  for (int chunk = 1; chunk * steps_per_chunk * x <= 10.0; ++chunk) {
    p.steps(steps_per_chunk);
    const double t = chunk * steps_per_chunk * dt;
    const double exact = v_terminal * (1.0 - std::exp(-kappa * t / p.mass));
    worst = std::max(worst, std::abs(p.vz() - exact) / std::abs(v_terminal));
  }
  return worst;
}

// Each step multiplies v - v_t by 1/(1 + x/2)^2 = exp(-x) (1 - x^2/4 + O(x^3)); after s = n x relaxation
// times the relative error is (x/4) s exp(-s), largest at s = 1: x / (4 e). First order in dt.
TEST(ImplicitDrag, FollowsTheExponentialRelaxationToFirstOrder) {
  for (double x : {0.02, 0.01, 0.005}) {
    const double measured = relaxationError(x);
    const double predicted = x / (4.0 * std::exp(1.0));
    std::printf("kappa dt/m = %.3f: max |v - v_exact| / |v_t| = %.3e, leading-order prediction %.3e\n", x, measured,
                predicted);
    EXPECT_NEAR(measured, predicted, 0.05 * predicted);
  }
}

TEST(ImplicitDrag, ReachesTheTerminalVelocityExactly) {
  const double dt = 1e-4;
  SingleParcel p(dt);
  const double kappa = 0.5 * p.mass / dt;
  p.set(kappa, 1.2);
  p.steps(400);
  const double v_terminal = 1.2 - p.mass * g / kappa;
  std::printf("steady state: v = %.15g, u_f + m g / kappa = %.15g\n", p.vz(), v_terminal);
  EXPECT_NEAR(p.vz(), v_terminal, 1e-12 * std::abs(v_terminal));
}

TEST(ImplicitDrag, StaysStableAndMonotoneForStiffDrag) {
  const double dt = 1e-4;
  SingleParcel p(dt);
  const double kappa = 100.0 * p.mass / dt;  // response time m / kappa = dt / 100
  p.set(kappa, -0.3);
  const double v_terminal = -0.3 - p.mass * g / kappa;
  double previous = std::abs(0.0 - v_terminal);
  for (int n = 0; n < 20; ++n) {
    p.steps(1);
    const double distance = std::abs(p.vz() - v_terminal);
    if (n == 0) {
      EXPECT_LT(distance, 0.01 * previous);  // one step removes 99 % of the initial slip
    }
    EXPECT_LE(distance, previous) << "step " << n;
    previous = distance;
  }
  std::printf("kappa dt/m = 100: |v - v_terminal| after 20 steps = %.2e\n", previous);
  EXPECT_LT(previous, 1e-12);
}
