// Columns gas_cfl, pressure_iterations: the gas Courant number and PCG iterations of the last gas step.
#pragma once

#include "monitor.h"

namespace parcelflow::coupling {

class GasStepMonitor : public Monitor {
 public:
  std::vector<std::string> columns() const override { return {"gas_cfl", "pressure_iterations"}; }
  void sample(const MonitorInput& in, std::vector<double>& row) const override {
    const cfd::StepReport& r = in.gas.lastReport();
    row.insert(row.end(), {r.cfl, static_cast<double>(r.pressureIterations)});
  }
};

}  // namespace parcelflow::coupling
