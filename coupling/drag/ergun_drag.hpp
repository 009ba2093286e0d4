#pragma once
// Ergun packed-bed drag law.
// Reference: S. Ergun, "Fluid flow through packed columns", Chem. Eng. Prog. 48 (1952) 89-94; two-fluid
// form as in D. Gidaspow, "Multiphase Flow and Fluidization" (1994), eq. (5.78):
//   beta = 150 a_s^2 mu / (a_g d_p^2) + 1.75 a_s rho_g |u - v| / d_p.
// Computed here as K = beta / a_s = 150 a_s mu / (a_g d_p^2) + 1.75 rho_g |u - v| / d_p.
// On its own it is meant for packed beds (verification against the Ergun pressure drop); note that
// K -> 1.75 rho |u-v| / d_p (no Stokes term) as a_s -> 0, which is why Gidaspow switches to Wen-Yu.
#include "coupling/drag/drag_input.hpp"

namespace parcelflow::coupling {

class ErgunDrag {
 public:
  static constexpr const char* typeName = "Ergun";
  static const char* reference();

  // K = beta / a_s [kg/(m^3 s)].
  double coefficient(const DragInput& in) const noexcept {
    const double alphaS = 1.0 - in.alphaG;
    return 150.0 * alphaS * in.muG / (in.alphaG * in.dp * in.dp) + 1.75 * in.rhoG * in.slip / in.dp;
  }
};

}  // namespace parcelflow::coupling
