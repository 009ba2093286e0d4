#include "coupling/drag/ergun_drag.hpp"

namespace parcelflow::coupling {

const char* ErgunDrag::reference() {
  return "Ergun, Chem. Eng. Prog. 48 (1952) 89; Gidaspow (1994) eq. 5.78";
}

}  // namespace parcelflow::coupling
