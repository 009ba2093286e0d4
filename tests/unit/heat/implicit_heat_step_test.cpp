// The implicit Euler step of a parcel's temperature against the lumped analytic solution
// T(t) = T_g + (T0 - T_g) exp(-t H/(M c)), for steps far below and far above the response time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "liggghts_plugins/parcel_heat_step.hpp"

using parcelflow::plugins::implicit_heat_step;

namespace {

// max over the steps of |T - T_exact| / |T0 - T_g| for n steps of dt = ratio * tau
double maxLumpedError(double ratio, int n) {
  const double mc = 2.1e-6, H = 7.0e-5, tau = mc / H, dt = ratio * tau, Tg = 600.0, T0 = 300.0;
  double T = T0, err = 0.0;
  for (int k = 1; k <= n; ++k) {
    T = implicit_heat_step(mc, T, dt, H, Tg, 0.0);
    const double exact = Tg + (T0 - Tg) * std::exp(-k * dt / tau);
    err = std::max(err, std::fabs(T - exact) / std::fabs(T0 - Tg));
  }
  return err;
}

}  // namespace

TEST(ImplicitHeatStep, FollowsTheLumpedSolutionWhenTheStepIsSmall) {
  // first order: the error peaks near t = tau at about (dt/tau)/2 * exp(-1)
  const double e1 = maxLumpedError(1e-3, 5000), e2 = maxLumpedError(5e-4, 10000);
  std::printf("[ heat ] dt/tau = 1e-3: max error %.3e of T0 - T_g; dt/tau = 5e-4: %.3e (ratio %.3f)\n", e1, e2,
              e1 / e2);
  EXPECT_LT(e1, 5e-3 * 0.1);  // far inside the 0.5 % the tests ask of the DEM runs
  EXPECT_NEAR(e1, 0.5e-3 * std::exp(-1.0), 0.1 * 0.5e-3 * std::exp(-1.0));
  EXPECT_NEAR(e1 / e2, 2.0, 0.02);  // observed order 1
}

TEST(ImplicitHeatStep, NoOvershootWhenTheStepIsFarAboveTheResponseTime) {
  const double mc = 1e-9, H = 1e-3, dt = 1e-3, Tg = 600.0;  // dt H/(M c) = 1000
  double T = 300.0;
  for (int k = 0; k < 20; ++k) {
    const double before = T;
    T = implicit_heat_step(mc, T, dt, H, Tg, 0.0);
    EXPECT_GE(T, before);
    EXPECT_LE(T, Tg);
  }
  EXPECT_NEAR(T, Tg, 1e-9);
  // one step closes all but 1/(1 + dt H/(M c)) of the gap
  EXPECT_NEAR(implicit_heat_step(mc, 300.0, dt, H, Tg, 0.0), Tg - 300.0 / 1001.0, 1e-10);
}

TEST(ImplicitHeatStep, SourceAndNoExchange) {
  // H = 0: explicit heating by Q, T + dt Q/(M c)
  EXPECT_DOUBLE_EQ(implicit_heat_step(2.0, 300.0, 0.5, 0.0, 999.0, 4.0), 301.0);
  // steady state with a source: T = T_g + Q/H
  EXPECT_NEAR(implicit_heat_step(2.0, 305.0, 0.5, 0.8, 300.0, 4.0), 305.0, 1e-12);
}

TEST(ImplicitHeatStep, AParcelOfNpEightHeatsAsEachOfItsParticles) {
  const double mc = 2.1e-6, H = 7.0e-5, dt = 1e-3, Tg = 600.0;
  double t1 = 300.0, t8 = 300.0;
  for (int k = 0; k < 1000; ++k) {
    t1 = implicit_heat_step(mc, t1, dt, H, Tg, 0.0);
    t8 = implicit_heat_step(8.0 * mc, t8, dt, 8.0 * H, Tg, 0.0);
    ASSERT_NEAR(t8, t1, 1e-12 * t1);
  }
}
