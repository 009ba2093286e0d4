#include "coupling/drag/beetstra_drag.hpp"

namespace parcelflow::coupling {

const char* BeetstraDrag::reference() {
  return "Beetstra, van der Hoef & Kuipers, AIChE J. 53 (2007) 489; van der Hoef et al., JFM 528 (2005) 233";
}

}  // namespace parcelflow::coupling
