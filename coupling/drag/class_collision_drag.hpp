#pragma once
// The momentum two classes of particles exchange by collisions, and the part of it that coarse-grained
// parcels do not exchange (issue 29: parcels of a size mixture segregate more than their particles).
// Reference: M. Syamlal, "The particle-particle drag term in a multiparticle model of fluidization", Topical
// Report DOE/MC/21353-2373 (1987); in the form of the MFIX theory guide (Syamlal, Rogers, O'Brien 1993):
//   force on class l per unit volume = F_lm (v_m - v_l),
//   F_lm = 3 (1 + e)(pi/2 + C_f pi^2/8) (d_l + d_m)^2 / (2 pi (rho_l d_l^3 + rho_m d_m^3))
//          a_l rho_l a_m rho_m g0_lm |v_l - v_m|,
// with Lebowitz's (1964) radial distribution of a mixture, g0_lm = 1/a_g + 3 d_l d_m / (a_g^2 (d_l + d_m))
// sum_k a_k / d_k. Parcels of collision diameter D = l d collide as spheres of D, so the DEM exchanges F_lm
// evaluated with the D's, which is F_lm(d) / l for one l (both the diameter factor and g0 are of degree -1
// and 0 in the diameters). The missing part, F_lm(d) - F_lm(D), is what this model adds; where the parcels
// exchange more than their particles (a small class under a much larger constant D) nothing can be taken
// away and the pair counts as not corrected.
#include <cstddef>

namespace parcelflow::coupling {

// One class of parcels in one cell.
struct CollisionClass {
  double solid_fraction = 0.0;  // a_k
  double density = 0.0;         // rho_k of the particles [kg/m^3]
  double diameter = 0.0;        // d_k of the real particles (a Sauter mean) [m]
  double parcel_diameter = 0.0; // D_k the parcels collide with [m]
  double velocity[3] = {0.0, 0.0, 0.0};  // mass-weighted mean velocity [m/s]
};

struct ClassCollisionParameters {
  double restitution = 0.9;  // e of the collisions between the classes
  double friction = 0.1;     // C_f, the coefficient of friction between them
};

class ClassCollisionDrag {
 public:
  static const char* reference();

  explicit ClassCollisionDrag(ClassCollisionParameters p) : p_(p) {}

  // F_lm / |v_l - v_m| [kg/(m^4)]: the exchange coefficient per unit relative speed of classes l and m of
  // diameters dl, dm in a cell of gas fraction alpha_g; sum_a_over_d = sum_k a_k / d_k over every class.
  double coefficientPerSpeed(const CollisionClass& l, const CollisionClass& m, double dl, double dm,
                             double alpha_g, double sum_a_over_d) const noexcept;

  // The accelerations [m/s^2] the missing collisions give each of the n classes of one cell (3 per class),
  // over one coupling interval dt. Each pair's exchange is bounded by what relaxes its relative velocity
  // exactly over dt at the start-of-step rate, (1 - exp(-r dt)) / (r dt) of the explicit value, so a
  // dense pair never overshoots. Momentum is conserved: sum_k a_k rho_k a_k = 0. Returns the pairs where
  // the parcels already exchange more than their particles (left uncorrected).
  int accelerations(const CollisionClass* classes, std::size_t n, double alpha_g, double dt, double* accel) const;

 private:
  ClassCollisionParameters p_;
};

}  // namespace parcelflow::coupling
