// Schumann's packed-bed solution (tests/support, the reference of the packed-bed breakthrough test): the
// Poisson form against the integral form, its limits, and the two equations it solves.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/schumann_packed_bed.hpp"

using parcelflow::testing::SchumannBed;
using parcelflow::testing::schumannJ;

namespace {

// 1 - int_0^x exp(-s - y) I0(2 sqrt(y s)) ds by composite Simpson (the form in the literature)
double integralJ(double x, double y)
{
  const int n = 20000;
  const double h = x / n;
  auto f = [y](double s) { return std::exp(-s - y) * std::cyl_bessel_i(0.0, 2.0 * std::sqrt(y * s)); };
  double sum = f(0.0) + f(x);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(i * h);
  return 1.0 - sum * h / 3.0;
}

}  // namespace

TEST(SchumannPackedBed, PoissonFormEqualsTheIntegral)
{
  for (double x : {0.3, 2.0, 10.0, 40.0})
    for (double y : {0.0, 0.5, 3.0, 12.0, 45.0})
      EXPECT_NEAR(schumannJ(x, y), integralJ(x, y), 1e-10) << "x " << x << " y " << y;
}

TEST(SchumannPackedBed, LimitsAndSymmetry)
{
  EXPECT_DOUBLE_EQ(schumannJ(0.0, 5.0), 1.0);                 // inlet gas: theta_g = 1
  EXPECT_NEAR(schumannJ(3.0, 0.0), std::exp(-3.0), 1e-15);   // the front: cold solid, gas decays as e^-xi
  for (double x : {0.7, 6.0, 25.0})
    for (double y : {0.2, 6.0, 30.0})  // J(x, y) + J(y, x) = 1 + exp(-x-y) I0(2 sqrt(x y))
      EXPECT_NEAR(schumannJ(x, y) + schumannJ(y, x),
                  1.0 + std::exp(-x - y) * std::cyl_bessel_i(0.0, 2.0 * std::sqrt(x * y)), 1e-12);
}

TEST(SchumannPackedBed, SolvesTheGasAndSolidEquations)
{
  // in xi, eta: d theta_g/d xi = theta_s - theta_g, d theta_s/d eta = theta_g - theta_s
  const double e = 1e-4;
  auto g = [](double xi, double eta) { return schumannJ(xi, eta); };
  auto s = [](double xi, double eta) { return 1.0 - schumannJ(eta, xi); };
  for (double xi : {0.5, 4.0, 15.0})
    for (double eta : {0.5, 4.0, 15.0}) {
      const double dg = (g(xi + e, eta) - g(xi - e, eta)) / (2 * e), ds = (s(xi, eta + e) - s(xi, eta - e)) / (2 * e);
      EXPECT_NEAR(dg, s(xi, eta) - g(xi, eta), 1e-7) << xi << " " << eta;
      EXPECT_NEAR(ds, g(xi, eta) - s(xi, eta), 1e-7) << xi << " " << eta;
    }
}

TEST(SchumannPackedBed, TheBedHoldsWhatTheGasBroughtIn)
{
  // per unit cross-section and per kelvin of T_in - T0: eps rho_g c_g u t entered by t; the bed holds
  // int (eps rho_g c_g theta_g + (1 - eps) rho_s c_s theta_s) dx (the heat front, at about 4 cm after
  // 100 s, is far from x = 0.3 m; the gas front, at 100 m, carries exp(-2e4))
  SchumannBed bed;
  const double t = 100.0, length = 0.3;
  const int n = 6000;
  const double h = length / n, cg = bed.porosity * bed.gas_density * bed.gas_heat_capacity,
               cs = (1.0 - bed.porosity) * bed.solid_density * bed.solid_heat_capacity;
  auto held = [&](double x) { return cg * bed.gas(x, t) + cs * bed.solid(x, t); };
  double sum = held(0.0) + held(length);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * held(i * h);
  const double stored = sum * h / 3.0, entered = cg * bed.interstitial_velocity * t;
  EXPECT_NEAR(stored / entered, 1.0, 1e-6);
  EXPECT_EQ(bed.gas(200.0, t), 0.0);  // the gas front has not reached x = 200 m
  EXPECT_NEAR(bed.gas(0.0, t), 1.0, 1e-15);
}
