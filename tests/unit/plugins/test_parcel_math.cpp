// dp <-> np <-> D and the linear collision scaling of hooke/stiffness.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "liggghts_plugins/parcel_math.h"

using namespace parcelflow::plugins;

TEST(ParcelMath, DiametersAndCounts)
{
  EXPECT_NEAR(particle_diameter(0.015, 27.0), 0.005, 1e-15);
  EXPECT_NEAR(particle_diameter(0.002, 8.0), 0.001, 1e-16);
  EXPECT_NEAR(particles_per_parcel(0.015, 0.005), 27.0, 1e-12);
  EXPECT_NEAR(particles_per_parcel(0.015, 150e-6), 1e6, 1e-6);
  for (double np : {1.0, 2.5, 8.0, 1000.0, 123456.0}) {
    const double D = 0.01;
    EXPECT_NEAR(particles_per_parcel(D, particle_diameter(D, np)) / np, 1.0, 1e-13);
    // equal solid volume: np dp^3 = D^3, so the parcel mass is np times the particle mass
    EXPECT_NEAR(np * std::pow(particle_diameter(D, np), 3) / (D * D * D), 1.0, 1e-13);
  }
}

TEST(ParcelMath, LinearScalingKeepsRestitutionAndScalesContactTime)
{
  const double m_p = 1e-3, kn = 1e4;  // particle mass, stiffness
  for (bool absolute : {false, true}) {
    HookeCoefficients c;
    c.kn = kn;
    c.kt = 2.0 / 7.0 * kn;
    c.absolute_damping = absolute;
    const double m_eff = 0.5 * m_p;
    const double gamma_abs = 0.3 * 2.0 * std::sqrt(kn * m_eff);  // damping ratio 0.3
    c.gamman = absolute ? gamma_abs : gamma_abs / m_eff;
    c.gammat = 0.5 * c.gamman;
    const double e1 = restitution_coefficient(kn, gamma_abs, m_eff);
    const double t1 = contact_duration(kn, gamma_abs, m_eff);
    for (double l : {1.0, 2.0, 3.0, 4.0, 10.0}) {
      const HookeCoefficients s = scale_linear(c, l);
      const double M_eff = l * l * l * m_eff;
      const double g_abs = absolute ? s.gamman : s.gamman * M_eff;
      const double e = restitution_coefficient(s.kn, g_abs, M_eff);
      const double t = contact_duration(s.kn, g_abs, M_eff);
      std::printf("[ scaling ] absolute_damping=%d l=%4.1f kn=%.4g kt=%.4g gamman=%.4g gammat=%.4g  e=%.12f (particle %.12f) "
                  "t_c/(l t_c1)=%.12f\n", absolute, l, s.kn, s.kt, s.gamman, s.gammat, e, e1, t / (l * t1));
      EXPECT_NEAR(e, e1, 1e-12);
      EXPECT_NEAR(t / (l * t1), 1.0, 1e-12);
      EXPECT_NEAR(s.kn, l * kn, 1e-9);
      EXPECT_NEAR(s.kt, l * c.kt, 1e-9);
      EXPECT_NEAR(s.gamman / c.gamman, absolute ? l * l : 1.0 / l, 1e-12);
      EXPECT_NEAR(s.gammat / c.gammat, absolute ? l * l : 1.0 / l, 1e-12);
    }
  }
}

// dp_by_type: two parcels of one diameter and mass holding particles of two sizes (one density). The pair's
// l = ((np_i + np_j)/2)^(1/3) makes linear scaling keep the particle pair's restitution and stretch its
// contact duration by l.
TEST(ParcelMath, EqualMassPairScaleFactorKeepsRestitution)
{
  const double D = 0.005, rho = 2526.0, kn = 100.0;
  auto mass = [&](double d) { return rho * M_PI / 6.0 * d * d * d; };
  for (const auto& [d_i, d_j] : {std::pair{0.0015, 0.0025}, std::pair{0.001, 0.004}, std::pair{0.002, 0.002}}) {
    const double m_eff = mass(d_i) * mass(d_j) / (mass(d_i) + mass(d_j)), M_eff = 0.5 * mass(D);
    const double l = equal_mass_pair_scale_factor(particles_per_parcel(D, d_i), particles_per_parcel(D, d_j));
    EXPECT_NEAR(l * l * l, M_eff / m_eff, 1e-12 * M_eff / m_eff);
    HookeCoefficients c;
    c.kn = kn;
    c.gamman = 0.05 * 2.0 * std::sqrt(kn / m_eff);  // mass-specific, damping ratio 0.05
    const HookeCoefficients s = scale_linear(c, l);
    const double e = restitution_coefficient(s.kn, s.gamman * M_eff, M_eff);
    const double e1 = restitution_coefficient(kn, c.gamman * m_eff, m_eff);
    const double t = contact_duration(s.kn, s.gamman * M_eff, M_eff);
    const double t1 = contact_duration(kn, c.gamman * m_eff, m_eff);
    std::printf("[ scaling ] dp_by_type D=%g dp %g/%g: l=%.6f e=%.12f (particles %.12f) t_c/(l t_c1)=%.12f\n", D, d_i,
                d_j, l, e, e1, t / (l * t1));
    EXPECT_NEAR(e, e1, 1e-12);
    EXPECT_NEAR(t / (l * t1), 1.0, 1e-12);
  }
  EXPECT_NEAR(equal_mass_pair_scale_factor(8.0, 8.0), 2.0, 1e-15);
}

// shear_stress: 1 - e'^2 = l^4 (1 - e^2), the restitution the Goldschmidt beads' parcels get (0.97: 0.922 at
// l = 2^(1/3), 0.837 at 1.5, 0.233 at 2), none beyond l = (1 - e^2)^(-1/4); the damping ratio of a restitution
// inverts restitution_coefficient.
TEST(ParcelMath, ShearStressRestitution)
{
  EXPECT_NEAR(shear_stress_restitution(0.97, 1.0), 0.97, 1e-15);
  EXPECT_NEAR(shear_stress_restitution(0.97, std::cbrt(2.0)), std::sqrt(1 - std::pow(2.0, 4.0 / 3) * 0.0591), 1e-12);
  EXPECT_NEAR(shear_stress_restitution(0.97, 1.5), std::sqrt(1 - 5.0625 * 0.0591), 1e-12);
  EXPECT_NEAR(shear_stress_restitution(0.97, 2.0), std::sqrt(1 - 16 * 0.0591), 1e-12);
  EXPECT_NEAR(shear_stress_restitution(0.97, 2.0), 0.2332, 1e-4);
  EXPECT_NEAR(largest_shear_stress_scale_factor(0.97), std::pow(0.0591, -0.25), 1e-12);  // 2.028
  EXPECT_NEAR(shear_stress_restitution(0.97, largest_shear_stress_scale_factor(0.97)), 0.0, 1e-6);
  EXPECT_TRUE(std::isnan(shear_stress_restitution(0.97, 2.1)));
  EXPECT_TRUE(std::isnan(shear_stress_restitution(0.7, 1.5)));  // 5.06 x 0.51 > 1
  const double kn = 1000.0, m_eff = 1e-5;
  for (double e : {0.97, 0.837, 0.5, 0.2332, 0.01}) {
    const double zeta = damping_ratio_of_restitution(e);
    const double g_abs = 2.0 * zeta * std::sqrt(kn * m_eff);
    EXPECT_NEAR(restitution_coefficient(kn, g_abs, m_eff), e, 1e-12) << e;
  }
  EXPECT_EQ(damping_ratio_of_restitution(0.0), 1.0);
}
