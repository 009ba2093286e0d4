#include "coupling/drag/radl_sundaresan_drag.hpp"

#include <string>

#include "cfd/base/internal_error.hpp"

namespace parcelflow::coupling {

const char* RadlSundaresanDrag::reference() {
  return "Radl & Sundaresan, Chem. Eng. Sci. 117 (2014) 416 (filtered correction; fits as in CFDEMcoupling-PFM "
         "BeetstraDrag.C) applied to Beetstra, van der Hoef & Kuipers, AIChE J. 53 (2007) 489";
}

RadlSundaresanDrag::RadlSundaresanDrag(const DragLawContext& context)
    : filterSize_(context.filterSize), gravity_(context.gravity), particleDensity_(context.particleDensity) {
  // The case reader has checked these (coupling.filtered_drag, gas.gravity, the mesh): a failure is a bug.
  PARCELFLOW_ASSERT(filterSize_ > 0.0 && gravity_ > 0.0 && particleDensity_ > 0.0,
                    std::string(typeName) + " needs a filter size, |g| and a particle density > 0, got " +
                        std::to_string(filterSize_) + " m, " + std::to_string(gravity_) + " m/s^2, " +
                        std::to_string(particleDensity_) + " kg/m^3");
}

}  // namespace parcelflow::coupling
