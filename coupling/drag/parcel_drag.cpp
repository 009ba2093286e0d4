#include "coupling/drag/parcel_drag.hpp"
#include "cfd/base/internal_error.hpp"

namespace parcelflow::coupling {

namespace drag_detail {
void checkBatch(const ParcelDragBatch& batch, const DragLimits& limits) {
  // The case reader has checked the floor and the gas properties: a failure here is a bug.
  PARCELFLOW_ASSERT(limits.alphaGFloor > 0.0 && limits.alphaGFloor < 1.0,
                    "drag: the gas-fraction floor must lie in (0, 1), got " + std::to_string(limits.alphaGFloor));
  PARCELFLOW_ASSERT(batch.rhoG > 0.0 && batch.muG > 0.0,
                    "drag: gas density and viscosity must be positive (rho_g = " + std::to_string(batch.rhoG) +
                        ", mu_g = " + std::to_string(batch.muG) + ")");
  PARCELFLOW_ASSERT(batch.size == 0 || (batch.alphaG && batch.slip && batch.dp && batch.np),
                    "drag: parcel batch is missing alphaG, slip, dp or np");
}
}  // namespace drag_detail

DragStats computeParcelKappa(const DragLaw& law, const ParcelDragBatch& batch, const DragLimits& limits,
                             double* kappa) {
  return forEachParcel(law, batch, limits, [kappa](std::size_t p, double, double k) { kappa[p] = k; });
}

}  // namespace parcelflow::coupling
