// Parcel arithmetic: diameters, particle counts, and the linear collision scaling of hooke/stiffness.
//
// A parcel holds np real particles of diameter dp and collides as one sphere of diameter
// D = dp np^(1/3) (same solid volume), so its mass is np m_p when the sphere has the particle density.
// l = D/dp is the coarse-graining ratio, np = l^3.
#pragma once

#include <algorithm>
#include <cmath>

namespace parcelflow::plugins {

inline double particle_diameter(double parcel_diameter, double np) { return parcel_diameter / std::cbrt(np); }
inline double particles_per_parcel(double parcel_diameter, double dp)
{
  const double l = parcel_diameter / dp;
  return l * l * l;
}

// Coefficients of LIGGGHTS' `model hooke/stiffness` for one type pair. With absolute_damping off the
// dampings are mass-specific (force = gamma * m_eff * v_n, [1/s]); with absolute_damping on they are
// absolute (force = gamma_abs * v_n, [kg/s]).
struct HookeCoefficients {
  double kn = 0, kt = 0, gamman = 0, gammat = 0;
  bool absolute_damping = false;
};

// Linear scaling (Radl et al. 2011, Bierwisch et al. 2009) from the particle to a parcel of l = D/dp.
// Normal relative motion of a contact: m_eff x'' + g_abs x' + k x = 0 with
//   omega0^2 = k/m_eff,  zeta = g_abs / (2 sqrt(k m_eff)),  e = exp(-pi zeta / sqrt(1 - zeta^2)),
//   t_c = pi / (omega0 sqrt(1 - zeta^2)).
// Parcels: m_eff -> l^3 m_eff. With k -> l k, sqrt(k m_eff) -> l^2 sqrt(k m_eff), so e (and the
// friction coefficient, which is not touched) stays the same when g_abs -> l^2 g_abs, i.e. the
// mass-specific g = g_abs/m_eff -> g/l. The contact duration grows as sqrt(m_eff/k) -> l t_c and the
// overlap relative to the diameter is kept: delta_max ~ v sqrt(m_eff/k) -> l delta_max.
// The tangential spring and damping are scaled the same way (kt with kn, gammat with gamman).
inline HookeCoefficients scale_linear(const HookeCoefficients& c, double l)
{
  HookeCoefficients s = c;
  s.kn = c.kn * l;
  s.kt = c.kt * l;
  const double damping_factor = c.absolute_damping ? l * l : 1.0 / l;
  s.gamman = c.gamman * damping_factor;
  s.gammat = c.gammat * damping_factor;
  return s;
}

// l of the contact of two parcels of the same mass M (one parcel diameter D, one density) holding np_i and
// np_j particles (dp_by_type: two size classes of one parcel diameter). Linear scaling keeps e exactly for
// any l that is the cube root of the ratio of the effective masses (scale_linear above), and here
//   M_eff / m_eff = (M/2) / (m_i m_j / (m_i + m_j)) = (M/m_i + M/m_j) / 2 = (np_i + np_j) / 2,
// so l = ((np_i + np_j) / 2)^(1/3), which is D/dp for np_i = np_j. Against a wall (infinite mass)
// M_eff / m_eff = M/m_i = np_i: l = D/dp_i.
inline double equal_mass_pair_scale_factor(double np_i, double np_j) { return std::cbrt(0.5 * (np_i + np_j)); }

// Damped linear oscillator of one normal contact (absolute damping g_abs [kg/s]).
inline double damping_ratio(double kn, double gamma_abs, double m_eff)
{
  return gamma_abs / (2.0 * std::sqrt(kn * m_eff));
}
inline double restitution_coefficient(double kn, double gamma_abs, double m_eff)
{
  const double z = damping_ratio(kn, gamma_abs, m_eff);
  return std::exp(-M_PI * z / std::sqrt(1.0 - z * z));
}
// The damping ratio that gives restitution e (restitution_coefficient inverted; 1, critical, at e = 0).
inline double damping_ratio_of_restitution(double e)
{
  if (!(e > 0.0)) return 1.0;
  const double ln = std::log(e);
  return -ln / std::sqrt(M_PI * M_PI + ln * ln);
}

// Parcel-parcel restitution e' that keeps the particles' collisional shear stress at one shear rate (dense
// kinetic theory: the granular temperature goes as d^2 (shear rate)^2 / (1 - e^2), the viscosity as
// d sqrt(temperature), so the shear stress as d^2 (shear rate)^2 / sqrt(1 - e^2)): 1 - e'^2 = l^4 (1 - e^2).
// NaN beyond largest_shear_stress_scale_factor(e), where no restitution >= 0 is dissipative enough.
inline double shear_stress_restitution(double e, double l)
{
  const double loss = l * l * l * l * (1.0 - e * e);
  if (loss > 1.0 + 1e-12) return std::nan("");
  return std::sqrt(std::max(0.0, 1.0 - loss));  // the rounding of l at the limit itself
}
inline double largest_shear_stress_scale_factor(double e) { return std::pow(1.0 - e * e, -0.25); }

inline double contact_duration(double kn, double gamma_abs, double m_eff)
{
  const double z = damping_ratio(kn, gamma_abs, m_eff);
  return M_PI / (std::sqrt(kn / m_eff) * std::sqrt(1.0 - z * z));
}

}  // namespace parcelflow::plugins
