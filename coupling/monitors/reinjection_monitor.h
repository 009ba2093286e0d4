// Columns of `fix parcel/reinject` (the cyclone emulation), when the LIGGGHTS script defines one: parcels and
// mass taken out at the outlet and put back at the return region since the previous row, those pending now
// (held by the fix, outside the bed), and the cumulative totals. Parcels in the bed plus pending ones are the
// parcels the run started with (tests/regression/plugins checks it at every step).
#pragma once

#include "liggghts_plugins/fix_parcel_reinject.h"
#include "coupling/monitors/monitor.h"

namespace parcelflow::coupling {

class ReinjectionMonitor : public Monitor {
 public:
  // The first row counts from the fix's state now (0 in a fresh run; a continued run starts from the
  // checkpoint, so a checkpoint between two rows splits that interval; the totals are exact either way).
  explicit ReinjectionMonitor(const plugins::FixParcelReinject& fix) {
    using Fix = plugins::FixParcelReinject;
    last_[0] = fix.counter(Fix::TOTAL_OUT_N);
    last_[1] = fix.counter(Fix::TOTAL_OUT_MASS);
    last_[2] = fix.counter(Fix::TOTAL_IN_N);
    last_[3] = fix.counter(Fix::TOTAL_IN_MASS);
  }
  std::vector<std::string> columns() const override {
    return {"reinjected_out", "reinjected_out_mass", "reinjected_in", "reinjected_in_mass",
            "reinjection_pending", "reinjection_pending_mass", "reinjected_out_total", "reinjected_in_total"};
  }
  void sample(const MonitorInput& in, std::vector<double>& row) const override {
    using Fix = plugins::FixParcelReinject;
    const Fix& fix = *in.parcels.reinjection();
    const double out = fix.counter(Fix::TOTAL_OUT_N), out_mass = fix.counter(Fix::TOTAL_OUT_MASS);
    const double put = fix.counter(Fix::TOTAL_IN_N), put_mass = fix.counter(Fix::TOTAL_IN_MASS);
    row.insert(row.end(), {out - last_[0], out_mass - last_[1], put - last_[2], put_mass - last_[3],
                           fix.counter(Fix::PENDING_N), fix.counter(Fix::PENDING_MASS), out, put});
    last_[0] = out;
    last_[1] = out_mass;
    last_[2] = put;
    last_[3] = put_mass;
  }

 private:
  mutable double last_[4];  // the cumulative values at the previous row
};

}  // namespace parcelflow::coupling
