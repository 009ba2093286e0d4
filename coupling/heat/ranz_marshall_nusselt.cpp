#include "coupling/heat/ranz_marshall_nusselt.hpp"

namespace parcelflow::coupling {

const char* RanzMarshallNusselt::reference() {
  return "Ranz & Marshall, Chem. Eng. Prog. 48 (1952) 141; single sphere, Re <= 200";
}

}  // namespace parcelflow::coupling
