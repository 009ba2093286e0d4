#include "coupling/heat/gunn_nusselt.hpp"

namespace parcelflow::coupling {

const char* GunnNusselt::reference() {
  return "Gunn, Int. J. Heat Mass Transfer 21 (1978) 467; valid 0.35 <= a_g <= 1, Re <= 1e5";
}

}  // namespace parcelflow::coupling
