// Columns mean_z_type<t>: the mass-weighted mean height of the parcels of each atom type (NaN for a type
// without parcels); the segregation of a bed of two size classes is read from them.
#pragma once

#include "coupling/monitors/monitor.h"

namespace parcelflow::coupling {

class MeanHeightMonitor : public Monitor {
 public:
  explicit MeanHeightMonitor(int ntypes) : ntypes_(ntypes) {}
  std::vector<std::string> columns() const override {
    std::vector<std::string> names;
    for (int t = 1; t <= ntypes_; ++t) names.push_back("mean_z_type" + std::to_string(t));
    return names;
  }
  void sample(const MonitorInput& in, std::vector<double>& row) const override {
    const std::vector<double> z = in.parcels.meanHeightPerType();
    row.insert(row.end(), z.begin(), z.end());
  }

 private:
  int ntypes_;
};

}  // namespace parcelflow::coupling
