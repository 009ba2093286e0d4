#pragma once
// Inputs of a drag law for one parcel, and the correlations shared by several laws.
//
// Conventions (DESIGN.md section 4, "model A" two-fluid form: the particles feel -V_p grad p separately):
//   beta  [kg/(m^3 s)]  gas-solid exchange coefficient per unit mixture volume,
//   K = beta / a_s      exchange coefficient per unit PARTICLE volume (what every law computes; finite
//                       as a_s -> 0, so kappa never divides by a tiny a_s),
//   kappa = np V_p K    the parcel's implicit drag coefficient [kg/s], V_p = pi d_p^3 / 6.
#include <cmath>

namespace parcelflow::coupling {

struct DragInput {
  double alphaG = 1.0;  // gas volume fraction a_g in (0, 1]; the caller floors it (DragLimits)
  double rhoG = 0.0;    // gas density [kg/m^3]
  double muG = 0.0;     // gas dynamic viscosity [Pa s]
  double dp = 0.0;      // REAL particle diameter [m] (not the parcel's collision diameter)
  double slip = 0.0;    // |u - v| [m/s], >= 0
  double dMean = 0.0;   // local Sauter-mean diameter <d> [m] (polydisperse BVK); <= 0 means "= dp"
};

// Per-case constants a law may need, given once when the law is made (makeDragLaw(name, context)) and
// stored in it: nothing is looked up per parcel. Laws that need none ignore it.
struct DragLawContext {
  double filterSize = 0.0;       // filter width Delta [m]: filter_cells x the gas cell size (V_cell)^(1/3)
  double gravity = 0.0;          // |g| [m/s^2]
  double particleDensity = 0.0;  // density of the real particles [kg/m^3]
};

namespace drag_detail {

// Particle Reynolds number Re = a_g rho_g |u - v| d / mu.
inline double reynolds(const DragInput& in, double d) noexcept {
  return in.alphaG * in.rhoG * in.slip * d / in.muG;
}

// C_D * |u - v| for the Schiller-Naumann type single-sphere curve used by Wen-Yu:
//   C_D = 24/Re (1 + 0.15 Re^0.687) for Re < 1000, else 0.44.
// Written without 1/Re so that it stays finite (-> 24 mu/(a_g rho d)) when |u - v| -> 0.
inline double cdTimesSlip(const DragInput& in) noexcept {
  const double re = reynolds(in, in.dp);
  if (re < 1000.0) {
    return 24.0 * in.muG / (in.alphaG * in.rhoG * in.dp) * (1.0 + 0.15 * std::pow(re, 0.687));
  }
  return 0.44 * in.slip;
}

}  // namespace drag_detail
}  // namespace parcelflow::coupling
