#pragma once
// The momentum two classes of particles exchange by collisions, and the part of it that coarse-grained
// parcels do not exchange (issue 29: parcels of a size mixture segregate more than their particles).
//
// Force on class l per unit volume, from smooth inelastic spheres whose relative velocity is Gaussian about
// the classes' mean slip u = v_m - v_l with variance s^2 = T_l + T_m per component (T: each class's granular
// temperature, its velocity variance per component):
//   F_l = c_lm J(|u|, s) u,   c_lm = 3 (1 + e) (1 + pi C_f / 4) (d_l + d_m)^2 / (2 pi (rho_l d_l^3 + rho_m d_m^3))
//                                    a_l rho_l a_m rho_m g0_lm,
//   J = (2 pi / |u|) integral_0^1 c E[x^2 sign(x)] dc,  x ~ N(|u| c, s^2)  (collisions along every normal),
// with Lebowitz's (1964) radial distribution of a mixture, g0_lm = 1/a_g + 3 d_l d_m / (a_g^2 (d_l + d_m))
// sum_k a_k / d_k. Without fluctuations (s = 0) J = pi |u| / 2 and F_l is Syamlal's solids-solids drag
// (M. Syamlal, DOE/MC/21353-2373, 1987; MFIX theory guide, with its friction factor 1 + pi C_f / 4); with
// slip small against the fluctuations J = (8/3) sqrt(pi / 2) s, the kinetic theory's linear drag between
// species (as Jenkins and Mancini 1987 derive it). In a bubbling bed the fluctuations are the larger.
//
// Parcels of collision diameter D = l d collide as spheres of D with the same slip and fluctuations, so the
// DEM exchanges c_lm(D) J, which is c_lm(d) J / l for one l (the diameter factor is of degree -1 and g0 of
// degree 0 in the diameters). The missing part, (c_lm(d) - c_lm(D)) J u, is what this model adds; where the
// parcels exchange more than their particles (a small class under a much larger constant D) nothing can be
// taken away and the pair counts as not corrected.
#include <cstddef>

namespace parcelflow::coupling {

// One class of parcels in one cell.
struct CollisionClass {
  double solid_fraction = 0.0;  // a_k
  double density = 0.0;         // rho_k of the particles [kg/m^3]
  double diameter = 0.0;        // d_k of the real particles (a Sauter mean) [m]
  double parcel_diameter = 0.0; // D_k the parcels collide with [m]
  double velocity[3] = {0.0, 0.0, 0.0};  // mass-weighted mean velocity [m/s]
  double temperature = 0.0;     // granular temperature: mass-weighted velocity variance per component [m^2/s^2]
};

struct ClassCollisionParameters {
  double restitution = 0.9;  // e of the collisions between the classes
  double friction = 0.1;     // C_f, the coefficient of friction between them
};

class ClassCollisionDrag {
 public:
  static const char* reference();

  explicit ClassCollisionDrag(ClassCollisionParameters p) : p_(p) {}

  // c_lm [kg/m^4] of classes l and m taken with diameters dl, dm in a cell of gas fraction alpha_g;
  // sum_a_over_d = sum_k a_k / d_k over every class, with the same kind of diameter.
  double pairCoefficient(const CollisionClass& l, const CollisionClass& m, double dl, double dm, double alpha_g,
                         double sum_a_over_d) const noexcept;

  // J(|u|, s) [m/s]: pi |u| / 2 for s = 0, (8/3) sqrt(pi/2) s for |u| -> 0.
  static double collisionSpeed(double slip, double spread) noexcept;

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
