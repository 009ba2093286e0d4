#include "coupling/drag/di_felice_drag.hpp"

namespace parcelflow::coupling {

const char* DiFeliceDrag::reference() {
  return "Di Felice, Int. J. Multiphase Flow 20 (1994) 153";
}

}  // namespace parcelflow::coupling
