#pragma once
// Wen & Yu drag law.
// Reference: C.Y. Wen, Y.H. Yu, "Mechanics of fluidization", Chem. Eng. Prog. Symp. Ser. 62 (1966)
// 100-111; two-fluid form as in D. Gidaspow, "Multiphase Flow and Fluidization" (1994), eq. (5.79):
//   beta = 3/4 C_D a_s a_g rho_g |u - v| a_g^-2.65 / d_p,
//   Re = a_g rho_g |u - v| d_p / mu,  C_D = 24/Re (1 + 0.15 Re^0.687) (Re < 1000), 0.44 otherwise.
// Computed here as K = beta / a_s = 3/4 (C_D |u - v|) rho_g a_g^-1.65 / d_p.
// Stokes limit (a_g -> 1, Re -> 0): V_p K -> 3 pi mu d_p.
#include "coupling/drag/drag_input.hpp"

namespace parcelflow::coupling {

class WenYuDrag {
 public:
  static constexpr const char* typeName = "WenYu";
  static const char* reference();

  // K = beta / a_s [kg/(m^3 s)].
  double coefficient(const DragInput& in) const noexcept {
    return 0.75 * drag_detail::cdTimesSlip(in) * in.rhoG * std::pow(in.alphaG, -1.65) / in.dp;
  }
};

}  // namespace parcelflow::coupling
