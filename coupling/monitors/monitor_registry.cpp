#include "coupling/monitors/monitor_registry.h"

#include <cmath>

#include "coupling/monitors/bed_pressure_drop_monitor.h"
#include "coupling/monitors/counters_monitor.h"
#include "coupling/monitors/gas_fraction_extremes_monitor.h"
#include "coupling/monitors/gas_step_monitor.h"
#include "coupling/monitors/mean_height_monitor.h"
#include "coupling/monitors/pressure_planes_monitor.h"
#include "coupling/monitors/reinjection_monitor.h"

namespace parcelflow::coupling {

std::vector<std::unique_ptr<Monitor>> makeMonitors(const MonitorSettings& settings, const cfd::Mesh& mesh,
                                                   const cfd::GasSettings& gas, const DemParcels& parcels) {
  std::vector<std::unique_ptr<Monitor>> m;
  if (settings.has_bed_pressure_drop)
    m.push_back(std::make_unique<BedPressureDropMonitor>(mesh, settings.bed_pressure_drop[0],
                                                         settings.bed_pressure_drop[1], gas.gas.density,
                                                         std::abs(gas.gas.gravity[2])));
  if (!settings.pressure_planes.empty())
    m.push_back(std::make_unique<PressurePlanesMonitor>(mesh, settings.pressure_planes));
  m.push_back(std::make_unique<MeanHeightMonitor>(parcels.ntypes()));
  m.push_back(std::make_unique<GasFractionExtremesMonitor>());
  m.push_back(std::make_unique<CountersMonitor>());
  m.push_back(std::make_unique<GasStepMonitor>());
  if (parcels.reinjection()) m.push_back(std::make_unique<ReinjectionMonitor>(*parcels.reinjection()));
  return m;
}

}  // namespace parcelflow::coupling
