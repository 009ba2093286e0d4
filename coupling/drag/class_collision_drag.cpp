#include "class_collision_drag.hpp"

#include <cmath>

namespace parcelflow::coupling {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

const char* ClassCollisionDrag::reference() {
  return "Syamlal (1987), DOE/MC/21353-2373, solids-solids drag with Lebowitz's g0; the part parcels of D = l d "
         "do not exchange";
}

double ClassCollisionDrag::coefficientPerSpeed(const CollisionClass& l, const CollisionClass& m, double dl,
                                               double dm, double alpha_g, double sum_a_over_d) const noexcept {
  const double g0 = 1.0 / alpha_g + 3.0 * dl * dm / (alpha_g * alpha_g * (dl + dm)) * sum_a_over_d;
  const double shape = 3.0 * (1.0 + p_.restitution) * (kPi / 2.0 + p_.friction * kPi * kPi / 8.0) *
                       (dl + dm) * (dl + dm) / (2.0 * kPi * (l.density * dl * dl * dl + m.density * dm * dm * dm));
  return shape * l.solid_fraction * l.density * m.solid_fraction * m.density * g0;
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
      const double missing = coefficientPerSpeed(l, m, l.diameter, m.diameter, alpha_g, sum_a_over_d) -
                             coefficientPerSpeed(l, m, l.parcel_diameter, m.parcel_diameter, alpha_g,
                                                 sum_a_over_parcel_d);
      if (missing < 0.0) {
        ++uncorrected;
        continue;
      }
      double dv[3], speed2 = 0.0;
      for (int d = 0; d < 3; ++d) {
        dv[d] = m.velocity[d] - l.velocity[d];
        speed2 += dv[d] * dv[d];
      }
      const double beta = missing * std::sqrt(speed2);
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
