#include "coupling/monitors/pressure_planes_monitor.h"

#include <cstdio>
#include <cstdlib>

namespace parcelflow::coupling {

std::string heightLabel(double z) {
  char buf[64];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, z);
    if (std::strtod(buf, nullptr) == z) break;
  }
  return buf;
}

PressurePlanesMonitor::PressurePlanesMonitor(const cfd::Mesh& mesh, const std::vector<double>& heights)
    : heights_(heights), planes_(mesh, heights, "monitors.pressure_planes") {}

std::vector<std::string> PressurePlanesMonitor::columns() const {
  std::vector<std::string> names;
  for (double z : heights_) names.push_back("p_z" + heightLabel(z));
  for (double z : heights_) names.push_back("gas_fraction_z" + heightLabel(z));
  return names;
}

void PressurePlanesMonitor::sample(const MonitorInput& in, std::vector<double>& row) const {
  const std::vector<double> p = planes_.meansAtHeights(in.gas.pressure(), in.gas.pressureGradient());
  const std::vector<double> a = planes_.means(in.gas_fraction);
  row.insert(row.end(), p.begin(), p.end());
  row.insert(row.end(), a.begin(), a.end());
}

}  // namespace parcelflow::coupling
