// Schumann's solution for a packed bed heated by a gas (T. E. W. Schumann, "Heat transfer: a liquid flowing
// through a porous prism", J. Franklin Inst. 208 (1929) 405-416): plug flow at interstitial velocity u,
// no conduction in gas or solid, gas-solid exchange h a_v per unit bed volume,
//   gas:   eps rho_g c_g (dT_g/dt + u dT_g/dx) = h a_v (T_s - T_g),
//   solid: (1 - eps) rho_s c_s dT_s/dt        = h a_v (T_g - T_s),
// bed initially at T0, inlet gas at T_in from t = 0. With
//   xi  = h a_v x / (eps rho_g c_g u),   eta = h a_v (t - x/u) / ((1 - eps) rho_s c_s)   (eta >= 0),
// theta = (T - T0)/(T_in - T0) is theta_g = J(xi, eta), theta_s = 1 - J(eta, xi), where
//   J(x, y) = 1 - int_0^x exp(-s - y) I0(2 sqrt(y s)) ds = P(N_x <= N_y),
// N_x and N_y independent Poisson variables of means x and y (expand I0 in powers of y s and integrate
// term by term: the k-th term is the Poisson weight of k at y times the Poisson probability of at most k
// at x). The Poisson form is evaluated here; the tests check it against the integral.
#pragma once

#include <cmath>

namespace parcelflow::testing {

// P(N_x <= N_y) for Poisson N_x, N_y of means x, y >= 0.
inline double schumannJ(double x, double y)
{
  if (x <= 0.0) return 1.0;
  const int kmax = static_cast<int>(y + 12.0 * std::sqrt(y + 1.0) + 40.0);
  double cdf_x = 0.0, sum = 0.0;
  for (int k = 0; k <= kmax; ++k) {
    cdf_x += std::exp(k * std::log(x) - x - std::lgamma(k + 1.0));
    const double pmf_y = y > 0.0 ? std::exp(k * std::log(y) - y - std::lgamma(k + 1.0)) : (k == 0 ? 1.0 : 0.0);
    sum += pmf_y * std::min(cdf_x, 1.0);
  }
  return sum;
}

struct SchumannBed {
  double porosity = 0.4;             // eps
  double gas_density = 1.2;          // rho_g [kg/m^3]
  double gas_heat_capacity = 1005;   // c_g [J/(kg K)]
  double interstitial_velocity = 1;  // u [m/s]
  double solid_density = 2500;       // rho_s [kg/m^3]
  double solid_heat_capacity = 840;  // c_s [J/(kg K)]
  double exchange = 1e5;             // h a_v [W/(m^3 K)]

  double xi(double x) const { return exchange * x / (porosity * gas_density * gas_heat_capacity * interstitial_velocity); }
  double eta(double x, double t) const
  {
    return exchange * (t - x / interstitial_velocity) / ((1.0 - porosity) * solid_density * solid_heat_capacity);
  }
  // theta of the gas and of the solid at depth x and time t (0 before the gas front arrives)
  double gas(double x, double t) const { return t < x / interstitial_velocity ? 0.0 : schumannJ(xi(x), eta(x, t)); }
  double solid(double x, double t) const
  {
    return t < x / interstitial_velocity ? 0.0 : 1.0 - schumannJ(eta(x, t), xi(x));
  }
};

}  // namespace parcelflow::testing
