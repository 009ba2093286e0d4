// Time averages from monitors.average.start on (the paper's Figures 7 and 8): the pressure on every monitor
// plane, and per cell the solids fraction a_s, the gas speed |u_g| and the solids speed |u_s|, each a
// time integral over the gas steps divided by the averaged time. From the averaged pressures:
//   - the profile dp/(g dz) between consecutive planes, -(p_{k+1} - p_k) / (g (z_{k+1} - z_k)), the bulk
//     density of the suspension there [kg/m3] (Figure 8);
//   - the bed height: where that profile first falls below half of its largest value, interpolated
//     linearly between the mid-heights of the intervals (NaN when it never does).
// The accumulators are part of every checkpoint (the plane sums in loop.yaml, the cell sums in
// averages.h5 keyed by global cell id), so a continued run averages on as if it had not stopped.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "cfd/output/field_writer.hpp"
#include "cfd/solver/gas_solver.hpp"
#include "coupling/monitors/plane_averages.h"

namespace parcelflow::coupling {

class TimeAverages {
 public:
  TimeAverages(const cfd::Mesh& mesh, const std::vector<double>& heights, double start, double gravity,
               const std::string& output_folder);

  // After a gas step ending at `time` of length dt: a_s as deposited, the solids velocity per owned cell
  // (interleaved xyz; zero where no parcel drags). Collective.
  void add(double time, double dt, const cfd::GasSolver& gas, const std::vector<double>& solid_fraction,
           const std::vector<double>& solids_velocity);

  double averagedTime() const { return duration_; }
  std::vector<double> meanPressure() const;
  // {mid-height, dp/(g dz)} per interval between consecutive planes.
  std::vector<std::pair<double, double>> bulkDensityProfile() const;
  double bedHeight() const;

  // averages.csv (plane heights, mean pressure; interval mid-heights, dp/(g dz); bed height) and a snapshot
  // of the averaged fields in averages.xdmf, at `time`. Collective.
  void write(double time);

  // Checkpoints: the plane sums and the averaged time by name, and the cell sums in an HDF5 file.
  std::map<std::string, std::vector<double>> save(const std::string& cell_file, const std::string& id) const;
  void restore(const std::map<std::string, std::vector<double>>& saved, const std::string& cell_file,
               const std::string& id);

 private:
  const cfd::Mesh& mesh_;
  std::vector<double> heights_;
  PlaneAverages planes_;
  double start_, gravity_;
  std::string folder_;
  double duration_ = 0.0;
  std::vector<double> pressure_sum_;                       // per plane, integral of p dt
  cfd::ScalarField solids_sum_, gas_speed_sum_, solids_speed_sum_;  // per owned cell, integrals over dt
  cfd::FieldWriter fields_;
};

}  // namespace parcelflow::coupling
