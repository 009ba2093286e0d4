// The missing class collisions (coupling/drag/class_collision_drag.hpp) against values computed here by hand,
// against an independent integration of the collisions' momentum transfer, and against the analytic relaxation
// of two classes' relative velocity (issue 29).
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/drag/class_collision_drag.hpp"

namespace pc = parcelflow::coupling;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The Goldschmidt beads: 1.5 and 2.5 mm glass, 0.3 of each, as parcels of l = D / d.
pc::CollisionClass bead(double d, double l, double a, double vz) {
  pc::CollisionClass c;
  c.solid_fraction = a;
  c.density = 2526.0;
  c.diameter = d;
  c.parcel_diameter = l * d;
  c.velocity[2] = vz;
  return c;
}

}  // namespace

// Without fluctuations the model is Syamlal's solids-solids drag.
TEST(ClassCollisionDrag, CoefficientIsSyamlalsWithLebowitzsRadialDistribution) {
  const pc::ClassCollisionDrag model({0.97, 0.1});
  const pc::CollisionClass small = bead(1.5e-3, 1.0, 0.3, 0.0), large = bead(2.5e-3, 1.0, 0.25, 0.0);
  const double ag = 0.45;
  const double sum = 0.3 / 1.5e-3 + 0.25 / 2.5e-3;  // 300 1/m
  // g0 = 1/0.45 + 3 (1.5e-3 * 2.5e-3) / (0.45^2 * 4e-3) * 300 = 2.2222 + 4.1667 = 6.3889
  const double g0 = 1.0 / 0.45 + 3.0 * 3.75e-6 / (0.2025 * 4e-3) * 300.0;
  EXPECT_NEAR(g0, 6.388889, 1e-6);
  // 3 (1.97)(pi/2 + 0.1 pi^2/8) (4e-3)^2 / (2 pi 2526 (1.5e-3^3 + 2.5e-3^3)) * (0.3 * 2526)(0.25 * 2526) * g0
  const double expected = 3.0 * 1.97 * (kPi / 2.0 + 0.1 * kPi * kPi / 8.0) * 16e-6 /
                          (2.0 * kPi * 2526.0 * (3.375e-9 + 15.625e-9)) * (0.3 * 2526.0) * (0.25 * 2526.0) * g0;
  const double slip = 0.1;
  EXPECT_NEAR(model.pairCoefficient(small, large, 1.5e-3, 2.5e-3, ag, sum) *
                  pc::ClassCollisionDrag::collisionSpeed(slip, 0.0) / slip,
              expected, 1e-9 * expected);
  EXPECT_NEAR(expected, 1.6242e6, 0.0001e6);  // kg/m^4: 0.1 m/s of slip exchanges 1.6e5 N/m^3
}

// J(|u|, s) against E[(pi/2) |g| g_z] / |u| for g ~ N(|u| z, s^2 I), integrated directly over g with scipy's
// dblquad (rho and z, 12 s each way, relative error 1e-11): an integration over the relative velocities, where
// the model integrates over the collision normals.
TEST(ClassCollisionDrag, CollisionSpeedIsTheMomentumTransferOfGaussianRelativeVelocities) {
  const double reference[][3] = {{0.01, 0.1, 0.33455120109044134}, {0.05, 0.05, 0.18325395971238007},
                                 {0.1, 0.02, 0.16939467591692903}, {0.2, 0.01, 0.3157280981903654},
                                 {0.001, 0.1, 0.3342204455159641}};
  for (const auto& r : reference)
    EXPECT_NEAR(pc::ClassCollisionDrag::collisionSpeed(r[0], r[1]), r[2], 1e-4 * r[2])
        << "slip " << r[0] << ", spread " << r[1];
  EXPECT_DOUBLE_EQ(pc::ClassCollisionDrag::collisionSpeed(0.3, 0.0), kPi / 2.0 * 0.3);
  EXPECT_DOUBLE_EQ(pc::ClassCollisionDrag::collisionSpeed(0.0, 0.1), 8.0 / 3.0 * std::sqrt(kPi / 2.0) * 0.1);
}

TEST(ClassCollisionDrag, ParcelsOfOneLMissTheShareOneMinusOneOverL) {
  const pc::ClassCollisionDrag model({0.97, 0.1});
  const double dt = 1e-12;  // the explicit limit: the bound changes the exchange by 1e-9
  for (double l : {1.0, 1.5, 2.0, 3.0}) {
    const pc::CollisionClass classes[2] = {bead(1.5e-3, l, 0.3, 0.2), bead(2.5e-3, l, 0.25, -0.1)};
    double accel[6];
    EXPECT_EQ(model.accelerations(classes, 2, 0.45, dt, accel), 0);
    const double full = model.pairCoefficient(classes[0], classes[1], 1.5e-3, 2.5e-3, 0.45,
                                              0.3 / 1.5e-3 + 0.25 / 2.5e-3) * kPi / 2.0 * 0.3;  // per dv
    const double expected_small = (1.0 - 1.0 / l) * full * (-0.3) / (0.3 * 2526.0);
    EXPECT_NEAR(accel[2], expected_small, 1e-6 * std::abs(full * 0.3 / 2526.0)) << "l = " << l;
    EXPECT_EQ(accel[0], 0.0);
    EXPECT_EQ(accel[1], 0.0);
  }
}

TEST(ClassCollisionDrag, ConservesMomentumOfThreeClasses) {
  const pc::ClassCollisionDrag model({0.9, 0.2});
  pc::CollisionClass classes[3] = {bead(1e-3, 2.0, 0.2, 0.3), bead(2e-3, 1.5, 0.15, -0.2), bead(3e-3, 2.5, 0.1, 0.05)};
  classes[0].velocity[0] = 0.1;
  classes[2].velocity[1] = -0.4;
  classes[1].density = 1500.0;
  double accel[9];
  model.accelerations(classes, 3, 0.55, 1e-4, accel);
  for (int d = 0; d < 3; ++d) {
    double sum = 0.0, scale = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double f = classes[k].solid_fraction * classes[k].density * accel[3 * k + d];
      sum += f;
      scale += std::abs(f);
    }
    EXPECT_GT(scale, 0.0);
    EXPECT_LT(std::abs(sum), 1e-13 * scale) << "axis " << d;
  }
}

// Without fluctuations: d(dv)/dt = -K |dv| dv with K = c (1/(rho a_l) + 1/(rho a_m)) gives dv(t) = dv0 / (1 + K dv0 t).
TEST(ClassCollisionDrag, RelativeVelocityRelaxesAsTheAnalyticSolution) {
  const pc::ClassCollisionDrag model({0.97, 0.1});
  pc::CollisionClass classes[2] = {bead(1.5e-3, 2.0, 0.3, 0.2), bead(2.5e-3, 2.0, 0.25, -0.1)};
  const double c = 0.5 * kPi / 2.0 *
                   model.pairCoefficient(classes[0], classes[1], 1.5e-3, 2.5e-3, 0.45, 0.3 / 1.5e-3 + 0.25 / 2.5e-3);
  const double K = c * (1.0 / (0.3 * 2526.0) + 1.0 / (0.25 * 2526.0));
  const double dv0 = 0.3, dt = 1e-6, end = 0.005;  // K dv0 end = 3.5: the slip falls to 0.22 of dv0
  double accel[6];
  const double momentum0 = 0.3 * 0.2 - 0.25 * 0.1;
  for (int step = 0; step < static_cast<int>(std::lround(end / dt)); ++step) {
    model.accelerations(classes, 2, 0.45, dt, accel);
    for (int k = 0; k < 2; ++k) classes[k].velocity[2] += dt * accel[3 * k + 2];
  }
  const double dv = classes[0].velocity[2] - classes[1].velocity[2];
  const double analytic = dv0 / (1.0 + K * dv0 * end);
  EXPECT_GT(K * dv0 * end, 3.0);
  EXPECT_NEAR(dv, analytic, 1e-3 * analytic);
  EXPECT_NEAR(0.3 * classes[0].velocity[2] + 0.25 * classes[1].velocity[2], momentum0, 1e-12);
}

// One step far longer than the relaxation time, with fluctuations: the pair relaxes by exp(-r dt), never past
// each other.
TEST(ClassCollisionDrag, ALongStepRelaxesThePairExactlyAtItsStartRate) {
  const pc::ClassCollisionDrag model({0.97, 0.1});
  pc::CollisionClass classes[2] = {bead(1.5e-3, 3.0, 0.3, 0.5), bead(2.5e-3, 3.0, 0.3, -0.5)};
  classes[0].temperature = 0.04;
  classes[1].temperature = 0.02;
  const double c = (1.0 - 1.0 / 3.0) * model.pairCoefficient(classes[0], classes[1], 1.5e-3, 2.5e-3, 0.4,
                                                             0.3 / 1.5e-3 + 0.3 / 2.5e-3);
  const double dt = 2e-3;
  const double rate_dt = c * pc::ClassCollisionDrag::collisionSpeed(1.0, std::sqrt(0.06)) * (2.0 / (0.3 * 2526.0)) * dt;
  EXPECT_GT(rate_dt, 5.0);
  double accel[6];
  model.accelerations(classes, 2, 0.4, dt, accel);
  const double dv = (0.5 + dt * accel[2]) - (-0.5 + dt * accel[5]);
  EXPECT_NEAR(dv, std::exp(-rate_dt), 1e-12);
  EXPECT_GT(dv, 0.0);
}

TEST(ClassCollisionDrag, NothingIsTakenWhereParcelsExchangeMoreThanTheirParticles) {
  const pc::ClassCollisionDrag model({0.97, 0.1});
  // a small class of 0.1 mm and a large one of 3 mm, both as parcels of 3 mm (constant parcel diameter)
  const pc::CollisionClass classes[2] = {bead(0.1e-3, 30.0, 0.2, 0.3), bead(3e-3, 1.0, 0.3, 0.0)};
  double accel[6];
  EXPECT_EQ(model.accelerations(classes, 2, 0.5, 1e-4, accel), 1);
  for (double a : accel) EXPECT_EQ(a, 0.0);
}
