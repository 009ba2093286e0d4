#include "coupling/drag/gidaspow_drag.hpp"

namespace parcelflow::coupling {

const char* GidaspowDrag::reference() {
  return "Gidaspow, Multiphase Flow and Fluidization (1994), eqs. 5.78-5.79";
}

}  // namespace parcelflow::coupling
