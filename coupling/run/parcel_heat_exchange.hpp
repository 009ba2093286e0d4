// The gas-particle heat exchange of one coupling step: the coupled implicit Euler step of the gas and each
// parcel over the coupling interval dt, conservative to round-off.
//
// Before the gas step, each parcel's conductance H = np h pi d_p^2 (a Nusselt correlation of its gathered
// a_g and slip, coupling/heat/) becomes H_eff = H M c/(M c + dt H), the conductance the gas sees toward the
// parcel's temperature at the start of the step when the parcel's own response is implicit too; the
// parcels deposit sum w H_eff [W/K] and sum w H_eff T_p [W] on the owned cells with the step's kernel
// weights (the gas energy equation's implicit exchange). After the gas step, the new gas temperature is
// gathered at the parcels with the same weights and each parcel gets S = H_eff (T_g - T_p) [W] to hold over
// the DEM run: exactly what the gas gave, and never more than brings the parcel to T_g (H_eff <= M c/dt).
// Parcels outside every fluid cell (orphans) exchange nothing.
#pragma once

#include <vector>

#include "coupling/heat/parcel_heat_transfer.hpp"
#include "coupling/run/parcel_mesh_coupler.h"

namespace parcelflow::coupling {

class ParcelHeatExchange {
 public:
  ParcelHeatExchange(NusseltCorrelation correlation, HeatLimits limits, GasThermalProperties gas);

  // After the coupler's computeDrag of this step (a_g and u gathered at the parcels in `at_parcels`):
  // temperature T_p [K] and heat capacity M c [J/K] per parcel of the step. Fills coeff and source per
  // owned cell.
  HeatStats depositExchange(ParcelMeshCoupler& coupler, const GasAtParcels& at_parcels, const double* temperature,
                            const double* heat_capacity, double dt, std::vector<double>& coeff,
                            std::vector<double>& source);

  // After the gas step: the gas temperature at the parcels (NaN for orphans) and each parcel's held source
  // S [W]. Returns the orphans.
  long gatherTemperature(ParcelMeshCoupler& coupler, const std::vector<double>& owned_temperature,
                         std::vector<double>& gas_temperature, std::vector<double>& held_source);

  const NusseltCorrelation& correlation() const { return correlation_; }

 private:
  NusseltCorrelation correlation_;
  HeatLimits limits_;
  GasThermalProperties gas_;
  // this step's, per parcel
  std::vector<double> effective_, temperature_, slip_, deposit_;
};

}  // namespace parcelflow::coupling
