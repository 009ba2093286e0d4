#include "coupling/monitors/bed_pressure_drop_monitor.h"

namespace parcelflow::coupling {

BedPressureDropMonitor::BedPressureDropMonitor(const cfd::Mesh& mesh, double z_low, double z_high,
                                               double gas_density, double gravity)
    : planes_(mesh, {z_low, z_high}, "monitors.bed_pressure_drop"),
      z_low_(z_low),
      gas_density_(gas_density),
      gravity_(gravity) {}

void BedPressureDropMonitor::sample(const MonitorInput& in, std::vector<double>& row) const {
  const std::vector<double> p = planes_.meansAtHeights(in.gas.pressure(), in.gas.pressureGradient());
  const double weight = in.parcels.buoyantWeightAbove(z_low_, gas_density_, gravity_);
  row.insert(row.end(), {p[0] - p[1], weight / planes_.layerArea(0)});
}

}  // namespace parcelflow::coupling
