// Columns gas_fraction_min, gas_fraction_max: the extremes of 1 - a_s as deposited (before the floor), so a
// bed packed below the floor shows here even though the gas never sees it.
#pragma once

#include <mpi.h>

#include <algorithm>

#include "coupling/monitors/monitor.h"

namespace parcelflow::coupling {

class GasFractionExtremesMonitor : public Monitor {
 public:
  std::vector<std::string> columns() const override { return {"gas_fraction_min", "gas_fraction_max"}; }
  void sample(const MonitorInput& in, std::vector<double>& row) const override {
    double local[2] = {1.0, 0.0};  // {min a_g, -max a_g}: one all-reduce
    for (double a_s : in.solid_fraction) {
      local[0] = std::min(local[0], 1.0 - a_s);
      local[1] = std::min(local[1], a_s - 1.0);
    }
    double global[2];
    MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MIN, in.gas.mesh().comm());
    row.insert(row.end(), {global[0], -global[1]});
  }
};

}  // namespace parcelflow::coupling
