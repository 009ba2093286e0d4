#include "coupling/heat/parcel_heat_transfer.hpp"

#include <string>

#include "cfd/base/internal_error.hpp"

namespace parcelflow::coupling {

namespace heat_detail {
void checkBatch(const ParcelHeatBatch& batch, const HeatLimits& limits) {
  // The case reader has checked the floor and the gas properties: a failure here is a bug.
  PARCELFLOW_ASSERT(limits.alphaGFloor > 0.0 && limits.alphaGFloor < 1.0,
                    "heat transfer: the gas-fraction floor must lie in (0, 1), got " +
                        std::to_string(limits.alphaGFloor));
  const GasThermalProperties& g = batch.gas;
  PARCELFLOW_ASSERT(g.rho > 0.0 && g.mu > 0.0 && g.conductivity > 0.0 && g.heatCapacity > 0.0,
                    "heat transfer: gas density, viscosity, conductivity and heat capacity must be positive (" +
                        std::to_string(g.rho) + ", " + std::to_string(g.mu) + ", " + std::to_string(g.conductivity) +
                        ", " + std::to_string(g.heatCapacity) + ")");
  PARCELFLOW_ASSERT(batch.size == 0 || (batch.alphaG && batch.slip && batch.dp && batch.np),
                    "heat transfer: parcel batch is missing alphaG, slip, dp or np");
}
}  // namespace heat_detail

HeatStats computeParcelConductance(const NusseltCorrelation& correlation, const ParcelHeatBatch& batch,
                                   const HeatLimits& limits, double* conductance) {
  return forEachParcelHeat(correlation, batch, limits,
                           [conductance](std::size_t p, double, double h) { conductance[p] = h; });
}

}  // namespace parcelflow::coupling
