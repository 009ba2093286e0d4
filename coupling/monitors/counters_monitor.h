// Columns of the run's counters (run_counters.h), summed over ranks and cumulative since the start of the
// run, and lost_parcels: parcels LIGGGHTS no longer has (for example under `thermo_modify lost ignore`).
#pragma once

#include "coupling/monitors/monitor.h"

namespace parcelflow::coupling {

class CountersMonitor : public Monitor {
 public:
  std::vector<std::string> columns() const override {
    std::vector<std::string> names;
    for (const auto& field : RunCounters{}.perRank()) names.emplace_back(field.first);
    names.emplace_back("lost_parcels");
    return names;
  }
  void sample(const MonitorInput& in, std::vector<double>& row) const override {
    RunCounters totals = in.counters.totals(in.gas.mesh().comm());
    for (const auto& field : totals.perRank()) row.push_back(static_cast<double>(*field.second));
    row.push_back(static_cast<double>(in.initial_parcels - in.parcels.globalCount()));
  }
};

}  // namespace parcelflow::coupling
