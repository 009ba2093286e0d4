// A monitor is one group of columns of monitors.csv: it names its columns once and appends exactly that
// many values per sample, so the header and the rows come from the same object and cannot drift.
// Monitors are built by name in monitor_registry.cpp; adding one is one file and one line there.
// sample() is collective: every rank calls it, rank 0's row is written.
#pragma once

#include <string>
#include <vector>

#include "cfd/solver/gas_solver.hpp"
#include "coupling/dem/dem_parcels.h"
#include "coupling/run/run_counters.h"

namespace parcelflow::coupling {

// What a monitor may read at a sample: the coupled state after a coupling step.
struct MonitorInput {
  double time = 0.0;
  const cfd::GasSolver& gas;
  const DemParcels& parcels;
  const std::vector<double>& gas_fraction;    // owned cells, as the gas saw it (floored)
  const std::vector<double>& solid_fraction;  // owned cells, as deposited (not floored)
  const RunCounters& counters;                // this rank's
  long initial_parcels = 0;
};

class Monitor {
 public:
  virtual ~Monitor() = default;
  virtual std::vector<std::string> columns() const = 0;
  virtual void sample(const MonitorInput& in, std::vector<double>& row) const = 0;
};

}  // namespace parcelflow::coupling
