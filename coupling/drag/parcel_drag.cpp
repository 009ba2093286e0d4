#include "parcel_drag.hpp"

namespace parcelflow::coupling {

namespace drag_detail {
void checkBatch(const ParcelDragBatch& batch, const DragLimits& limits) {
  if (!(limits.alphaGFloor > 0.0 && limits.alphaGFloor < 1.0))
    throw std::invalid_argument("drag: the gas-fraction floor must lie in (0, 1), got " +
                                std::to_string(limits.alphaGFloor));
  if (!(batch.rhoG > 0.0) || !(batch.muG > 0.0))
    throw std::invalid_argument("drag: gas density and viscosity must be positive (rho_g = " +
                                std::to_string(batch.rhoG) + ", mu_g = " + std::to_string(batch.muG) + ")");
  if (batch.size > 0 && (!batch.alphaG || !batch.slip || !batch.dp || !batch.np))
    throw std::invalid_argument("drag: parcel batch is missing alphaG, slip, dp or np");
}
}  // namespace drag_detail

DragStats computeParcelKappa(const DragLaw& law, const ParcelDragBatch& batch, const DragLimits& limits,
                             double* kappa) {
  return forEachParcel(law, batch, limits, [kappa](std::size_t p, double, double k) { kappa[p] = k; });
}

}  // namespace parcelflow::coupling
