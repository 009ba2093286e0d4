#pragma once
// Di Felice drag law.
// Reference: R. Di Felice, "The voidage function for fluid-particle interaction systems",
// Int. J. Multiphase Flow 20 (1994) 153-159. Force on one particle (superficial slip a_g |u - v|):
//   F = C_D rho_g (pi d_p^2 / 8) a_g^2 |u - v| (u - v) a_g^-chi,
//   C_D = (0.63 + 4.8 / sqrt(Re))^2,  Re = a_g rho_g |u - v| d_p / mu,
//   chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2).
// With n = a_s / V_p particles per volume: beta = 3/4 C_D rho_g a_s a_g^(2 - chi) |u - v| / d_p, so
//   K = beta / a_s = 3/4 (C_D |u - v|) rho_g a_g^(2 - chi) / d_p, and
//   C_D |u - v| = (0.63 sqrt|u - v| + 4.8 sqrt(mu / (a_g rho_g d_p)))^2  (finite as |u - v| -> 0;
//   chi -> 3.7 there, the exp term underflows to 0 exactly as in the formula's limit).
#include "coupling/drag/drag_input.hpp"

namespace parcelflow::coupling {

class DiFeliceDrag {
 public:
  static constexpr const char* typeName = "DiFelice";
  static const char* reference();

  static double exponentChi(double re) noexcept {
    if (!(re > 0.0)) return 3.7;  // limit Re -> 0: exp(-inf) = 0
    const double t = 1.5 - std::log10(re);
    return 3.7 - 0.65 * std::exp(-0.5 * t * t);
  }

  // K = beta / a_s [kg/(m^3 s)].
  double coefficient(const DragInput& in) const noexcept {
    const double re = drag_detail::reynolds(in, in.dp);
    const double root = 0.63 * std::sqrt(in.slip) + 4.8 * std::sqrt(in.muG / (in.alphaG * in.rhoG * in.dp));
    return 0.75 * root * root * in.rhoG * std::pow(in.alphaG, 2.0 - exponentChi(re)) / in.dp;
  }
};

}  // namespace parcelflow::coupling
