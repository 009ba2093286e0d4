#include "coupling/drag/wen_yu_drag.hpp"

namespace parcelflow::coupling {

const char* WenYuDrag::reference() {
  return "Wen & Yu, Chem. Eng. Prog. Symp. Ser. 62 (1966) 100; Gidaspow (1994) eq. 5.79";
}

}  // namespace parcelflow::coupling
