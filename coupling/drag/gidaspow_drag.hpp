#pragma once
// Gidaspow drag law: Ergun in dense regions, Wen-Yu in dilute regions, with a hard switch.
// Reference: D. Gidaspow, "Multiphase Flow and Fluidization", Academic Press (1994), eqs. (5.78)-(5.79);
// also MFiX DRAG_GIDASPOW (model/drag_gs.f):
//   beta = Wen-Yu           for a_g >  0.8,
//   beta = Ergun            for a_g <= 0.8.
// The law is discontinuous at a_g = 0.8 (Ergun/Wen-Yu = 1.10 at 0.01 m/s slip, 1.90 at 5 m/s for 0.5 mm
// particles in air); see GidaspowBlendDrag for the smooth variant.
#include "coupling/drag/ergun_drag.hpp"
#include "coupling/drag/wen_yu_drag.hpp"

namespace parcelflow::coupling {

class GidaspowDrag {
 public:
  static constexpr const char* typeName = "Gidaspow";
  static constexpr double switchAlphaG = 0.8;
  static const char* reference();

  // K = beta / a_s [kg/(m^3 s)].
  double coefficient(const DragInput& in) const noexcept {
    return in.alphaG > switchAlphaG ? WenYuDrag{}.coefficient(in) : ErgunDrag{}.coefficient(in);
  }
};

}  // namespace parcelflow::coupling
