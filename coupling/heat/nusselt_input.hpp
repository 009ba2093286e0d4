#pragma once
// Inputs of a gas-particle Nusselt correlation for one parcel.
//
// Conventions (the same as the drag laws'):
//   Re = a_g rho_g |u - v| d_p / mu_g  with the REAL particle diameter d_p (never the parcel's),
//   Pr = c_g mu_g / k_g,
//   h  = Nu k_g / d_p                   gas-particle heat transfer coefficient [W/(m^2 K)],
//   H  = np h pi d_p^2                  the parcel's conductance [W/K]: np real particles, each with its own
//                                       surface, so a parcel heats exactly as each of its particles.
namespace parcelflow::coupling {

struct NusseltInput {
  double alphaG = 1.0;    // gas volume fraction a_g in (0, 1]; the caller floors it (HeatLimits)
  double reynolds = 0.0;  // a_g rho_g |u - v| d_p / mu_g, >= 0
  double prandtl = 0.0;   // c_g mu_g / k_g, > 0
};

// Re of one parcel; the caller has checked mu_g > 0.
inline double particleReynolds(double alphaG, double rhoG, double slip, double dp, double muG) noexcept {
  return alphaG * rhoG * slip * dp / muG;
}

}  // namespace parcelflow::coupling
