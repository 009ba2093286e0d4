// Columns bed_pressure_drop, bed_weight_per_area: p(z_low) - p(z_high) at the exact heights, and what that
// drop carries on average in a fluidized bed, the buoyant weight of the parcels above z_low per area of the
// lower plane's layer (the drop also holds the gas's own rho_g g dz).
#pragma once

#include "coupling/monitors/monitor.h"
#include "coupling/monitors/plane_averages.h"

namespace parcelflow::coupling {

class BedPressureDropMonitor : public Monitor {
 public:
  BedPressureDropMonitor(const cfd::Mesh& mesh, double z_low, double z_high, double gas_density, double gravity);
  std::vector<std::string> columns() const override { return {"bed_pressure_drop", "bed_weight_per_area"}; }
  void sample(const MonitorInput& in, std::vector<double>& row) const override;

 private:
  PlaneAverages planes_;
  double z_low_, gas_density_, gravity_;
};

}  // namespace parcelflow::coupling
