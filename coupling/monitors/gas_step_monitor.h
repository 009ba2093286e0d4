// Columns gas_cfl, pressure_iterations, momentum_iterations, continuity_error: the gas Courant number, the
// PCG iterations (summed over the PISO correctors), the BiCGStab iterations (summed over the components)
// and the continuity error (StepReport::continuityError, the quantity coupling.guards.max_continuity_error
// bounds in every step) of the last gas step.
#pragma once

#include "coupling/monitors/monitor.h"

namespace parcelflow::coupling {

class GasStepMonitor : public Monitor {
 public:
  std::vector<std::string> columns() const override {
    return {"gas_cfl", "pressure_iterations", "momentum_iterations", "continuity_error"};
  }
  void sample(const MonitorInput& in, std::vector<double>& row) const override {
    const cfd::StepReport& r = in.gas.lastReport();
    row.insert(row.end(), {r.cfl, static_cast<double>(r.pressureIterations),
                           static_cast<double>(r.momentumIterations), r.continuityError});
  }
};

}  // namespace parcelflow::coupling
