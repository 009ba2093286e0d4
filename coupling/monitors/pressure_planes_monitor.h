// Columns p_z<h> and gas_fraction_z<h> for every height h of monitors.pressure_planes: the mean pressure at
// the exact height (each cell's p carried there with its grad p) and the mean gas fraction of the cell layer
// that contains it (plane_averages.h).
#pragma once

#include "coupling/monitors/monitor.h"
#include "coupling/monitors/plane_averages.h"

namespace parcelflow::coupling {

class PressurePlanesMonitor : public Monitor {
 public:
  PressurePlanesMonitor(const cfd::Mesh& mesh, const std::vector<double>& heights);
  std::vector<std::string> columns() const override;
  void sample(const MonitorInput& in, std::vector<double>& row) const override;

 private:
  std::vector<double> heights_;
  PlaneAverages planes_;
};

// A height as a column label: the shortest decimal form that reads back exactly (0.05, not 0.0500000001).
std::string heightLabel(double z);

}  // namespace parcelflow::coupling
