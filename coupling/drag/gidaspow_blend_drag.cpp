#include "coupling/drag/gidaspow_blend_drag.hpp"

namespace parcelflow::coupling {

const char* GidaspowBlendDrag::reference() {
  return "Huilin & Gidaspow, Chem. Eng. Sci. 58 (2003) 3777";
}

}  // namespace parcelflow::coupling
