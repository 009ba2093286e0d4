#include "coupling/drag/class_collision_drag.hpp"

#include <cmath>

namespace parcelflow::coupling {

namespace {

constexpr double kPi = 3.14159265358979323846;

// 8-point Gauss-Legendre nodes and weights on [0, 1].
constexpr double kNode[8] = {0.019855071751231912, 0.10166676129318664, 0.2372337950418355, 0.4082826787521751,
                             0.5917173212478248,   0.7627662049581645,  0.8983332387068134, 0.9801449282487681};
constexpr double kWeight[8] = {0.050614268145188344, 0.11119051722668717, 0.15685332293894352, 0.18134189168918088,
                               0.18134189168918088,  0.15685332293894352, 0.11119051722668717, 0.050614268145188344};

}  // namespace

const char* ClassCollisionDrag::reference() {
  return "Syamlal (1987) solids-solids drag with the classes' fluctuations (Jenkins and Mancini 1987) and Lebowitz's "
         "g0; the part parcels of D = l d do not exchange";
}

double ClassCollisionDrag::pairCoefficient(const CollisionClass& l, const CollisionClass& m, double dl, double dm,
                                           double alpha_g, double sum_a_over_d) const noexcept {
  const double g0 = 1.0 / alpha_g + 3.0 * dl * dm / (alpha_g * alpha_g * (dl + dm)) * sum_a_over_d;
  const double shape = 3.0 * (1.0 + p_.restitution) * (1.0 + kPi * p_.friction / 4.0) * (dl + dm) * (dl + dm) /
                       (2.0 * kPi * (l.density * dl * dl * dl + m.density * dm * dm * dm));
  return shape * l.solid_fraction * l.density * m.solid_fraction * m.density * g0;
}

double ClassCollisionDrag::collisionSpeed(double slip, double spread) noexcept {
  if (spread <= 0.0) return kPi / 2.0 * slip;
  if (slip <= 0.0) return 8.0 / 3.0 * std::sqrt(kPi / 2.0) * spread;
  // E[x^2 sign(x)] for x ~ N(mu, s^2) = (mu^2 + s^2) erf(mu / (s sqrt 2)) + 2 mu s phi(mu / s), divided by |u|
  double sum = 0.0;
  for (int q = 0; q < 8; ++q) {
    const double c = kNode[q], mu = slip * c, z = mu / spread;
    const double moment = (mu * mu + spread * spread) * std::erf(z / std::sqrt(2.0)) / slip +
                          2.0 * c * spread * std::exp(-0.5 * z * z) / std::sqrt(2.0 * kPi);
    sum += kWeight[q] * c * moment;
  }
  return 2.0 * kPi * sum;
}

int ClassCollisionDrag::accelerations(const CollisionClass* classes, std::size_t n, double alpha_g, double dt,
                                      double* accel) const {
  for (std::size_t k = 0; k < 3 * n; ++k) accel[k] = 0.0;
  double sum_a_over_d = 0.0, sum_a_over_parcel_d = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    if (classes[k].solid_fraction > 0.0) {
      sum_a_over_d += classes[k].solid_fraction / classes[k].diameter;
      sum_a_over_parcel_d += classes[k].solid_fraction / classes[k].parcel_diameter;
    }
  int uncorrected = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const CollisionClass& l = classes[i];
      const CollisionClass& m = classes[j];
      if (l.solid_fraction <= 0.0 || m.solid_fraction <= 0.0) continue;
      const double missing = pairCoefficient(l, m, l.diameter, m.diameter, alpha_g, sum_a_over_d) -
                             pairCoefficient(l, m, l.parcel_diameter, m.parcel_diameter, alpha_g, sum_a_over_parcel_d);
      if (missing < 0.0) {
        ++uncorrected;
        continue;
      }
      double dv[3], speed2 = 0.0;
      for (int d = 0; d < 3; ++d) {
        dv[d] = m.velocity[d] - l.velocity[d];
        speed2 += dv[d] * dv[d];
      }
      const double beta = missing * collisionSpeed(std::sqrt(speed2), std::sqrt(l.temperature + m.temperature));
      const double bulk_l = l.solid_fraction * l.density, bulk_m = m.solid_fraction * m.density;
      const double rate_dt = beta * (1.0 / bulk_l + 1.0 / bulk_m) * dt;
      const double bounded = rate_dt > 1e-12 ? -std::expm1(-rate_dt) / rate_dt : 1.0;
      for (int d = 0; d < 3; ++d) {
        const double force = beta * bounded * dv[d];  // on class l per unit volume
        accel[3 * i + d] += force / bulk_l;
        accel[3 * j + d] -= force / bulk_m;
      }
    }
  return uncorrected;
}

}  // namespace parcelflow::coupling
