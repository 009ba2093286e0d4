#pragma once
// Smooth Ergun / Wen-Yu blend (arctan switch).
// Reference: L. Huilin, D. Gidaspow, "Hydrodynamics of binary fluidization in a riser: CFD simulation
// using two granular temperatures", Chem. Eng. Sci. 58 (2003) 3777-3792; also MFiX
// DRAG_GIDASPOW_BLEND (model/drag_gs.f):
//   phi  = 1/2 + arctan(262.5 (a_g - 0.8)) / pi     (262.5 = 150 * 1.75)
//   beta = (1 - phi) beta_Ergun + phi beta_WenYu.
// phi = 1/2 exactly at a_g = 0.8; phi -> 1 (Wen-Yu) in dilute and -> 0 (Ergun) in dense regions.
#include "coupling/drag/ergun_drag.hpp"
#include "coupling/drag/wen_yu_drag.hpp"

namespace parcelflow::coupling {

class GidaspowBlendDrag {
 public:
  static constexpr const char* typeName = "GidaspowBlend";
  static const char* reference();

  static double blendFactor(double alphaG) noexcept {
    return 0.5 + std::atan(262.5 * (alphaG - 0.8)) / 3.14159265358979323846;
  }

  // K = beta / a_s [kg/(m^3 s)].
  double coefficient(const DragInput& in) const noexcept {
    const double phi = blendFactor(in.alphaG);
    return (1.0 - phi) * ErgunDrag{}.coefficient(in) + phi * WenYuDrag{}.coefficient(in);
  }
};

}  // namespace parcelflow::coupling
