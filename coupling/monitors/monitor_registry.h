// The monitors of a case, in their column order: those configured under `monitors:` in case.yaml, those
// every run writes (mean height per type, gas-fraction extremes, counters, the gas step), and the outlet
// reinjection's when the LIGGGHTS script has `fix parcel/reinject`.
#pragma once

#include <memory>
#include <vector>

#include "cfd/solver/gas_settings.hpp"
#include "coupling/run/coupling_settings.h"
#include "coupling/monitors/monitor.h"

namespace parcelflow::coupling {

std::vector<std::unique_ptr<Monitor>> makeMonitors(const MonitorSettings& settings, const cfd::Mesh& mesh,
                                                   const cfd::GasSettings& gas, const DemParcels& parcels);

}  // namespace parcelflow::coupling
