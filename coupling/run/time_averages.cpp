#include "coupling/run/time_averages.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "cfd/base/config_error.hpp"
#include "cfd/io/hdf5_file.hpp"

namespace parcelflow::coupling {

TimeAverages::TimeAverages(const cfd::Mesh& mesh, const std::vector<double>& heights, double start, double gravity,
                           const std::string& output_folder)
    : mesh_(mesh),
      heights_(heights),
      planes_(mesh, heights, "monitors.pressure_planes"),
      start_(start),
      gravity_(gravity),
      folder_(output_folder),
      pressure_sum_(heights.size(), 0.0),
      solids_sum_(mesh.nOwnedCells(), 0.0),
      gas_speed_sum_(mesh.nOwnedCells(), 0.0),
      solids_speed_sum_(mesh.nOwnedCells(), 0.0),
      fields_(mesh, output_folder, cfd::series::averages) {}

void TimeAverages::add(double time, double dt, const cfd::GasSolver& gas, const std::vector<double>& solid_fraction,
                       const std::vector<double>& solids_velocity) {
  // A step counts whole once it ends after the start (the start is meant as a multiple of the gas step).
  if (time <= start_ + 1e-9 * dt) return;
  const std::vector<double> p = planes_.meansAtHeights(gas.pressure(), gas.pressureGradient());
  for (std::size_t k = 0; k < p.size(); ++k) pressure_sum_[k] += p[k] * dt;
  for (int c = 0; c < mesh_.nOwnedCells(); ++c) {
    solids_sum_[c] += solid_fraction[c] * dt;
    gas_speed_sum_[c] += gas.velocity()[c].norm() * dt;
    const double* us = &solids_velocity[3 * static_cast<std::size_t>(c)];
    solids_speed_sum_[c] += std::sqrt(us[0] * us[0] + us[1] * us[1] + us[2] * us[2]) * dt;
  }
  duration_ += dt;
}

std::vector<double> TimeAverages::meanPressure() const {
  std::vector<double> mean(pressure_sum_.size(), std::numeric_limits<double>::quiet_NaN());
  if (duration_ > 0.0)
    for (std::size_t k = 0; k < mean.size(); ++k) mean[k] = pressure_sum_[k] / duration_;
  return mean;
}

std::vector<std::pair<double, double>> TimeAverages::bulkDensityProfile() const {
  const std::vector<double> p = meanPressure();
  std::vector<std::pair<double, double>> profile;
  for (std::size_t k = 0; k + 1 < p.size(); ++k)
    profile.emplace_back(0.5 * (heights_[k] + heights_[k + 1]),
                         -(p[k + 1] - p[k]) / (gravity_ * (heights_[k + 1] - heights_[k])));
  return profile;
}

double TimeAverages::bedHeight() const {
  const auto profile = bulkDensityProfile();
  double largest = 0.0;
  for (const auto& [z, rho] : profile) largest = std::max(largest, rho);
  const double half = 0.5 * largest;
  for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
    const auto [z0, r0] = profile[k];
    const auto [z1, r1] = profile[k + 1];
    if (r0 >= half && r1 < half) return z0 + (r0 - half) / (r0 - r1) * (z1 - z0);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

void TimeAverages::write(double time) {
  const int n = mesh_.nOwnedCells();
  cfd::ScalarField solids(n, 0.0), gas_speed(n, 0.0), solids_speed(n, 0.0);
  if (duration_ > 0.0)
    for (int c = 0; c < n; ++c) {
      solids[c] = solids_sum_[c] / duration_;
      gas_speed[c] = gas_speed_sum_[c] / duration_;
      solids_speed[c] = solids_speed_sum_[c] / duration_;
    }
  fields_.addScalar("mean_solids_fraction", solids);
  fields_.addScalar("mean_gas_speed", gas_speed);
  fields_.addScalar("mean_solids_speed", solids_speed);
  fields_.write(time);
  if (mesh_.rank() != 0) return;
  const std::string path = folder_ + "/averages.csv", partial = path + ".partial";
  std::FILE* f = std::fopen(partial.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write " + partial);
  std::fprintf(f, "# time averages over %.10g s from t = %.10g s, written at t = %.10g s; bed height %.10g m\n",
               duration_, start_, time, bedHeight());
  std::fprintf(f, "z,mean_pressure,interval_mid_z,dp_over_g_dz\n");
  const std::vector<double> p = meanPressure();
  const auto profile = bulkDensityProfile();
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (k < profile.size())
      std::fprintf(f, "%.10g,%.10g,%.10g,%.10g\n", heights_[k], p[k], profile[k].first, profile[k].second);
    else
      std::fprintf(f, "%.10g,%.10g,,\n", heights_[k], p[k]);
  }
  const bool ok = std::fflush(f) == 0;
  if (std::fclose(f) != 0 || !ok || std::rename(partial.c_str(), path.c_str()) != 0)
    throw std::runtime_error("cannot write " + path);
}

std::map<std::string, std::vector<double>> TimeAverages::save(const std::string& cell_file,
                                                               const std::string& id) const {
  const int n = mesh_.nOwnedCells();
  std::vector<long long> cells(n);
  for (int c = 0; c < n; ++c) cells[c] = mesh_.globalId(c);
  const long total = mesh_.nGlobalCells(), offset = cfd::rowOffset(n, mesh_.comm());
  cfd::Hdf5Writer file(cell_file, mesh_.comm());
  file.attribute("checkpoint_id", id);
  file.write("cell_id", cells.data(), total, offset, n, 1);
  file.write("solids_fraction_sum", solids_sum_.data(), total, offset, n, 1);
  file.write("gas_speed_sum", gas_speed_sum_.data(), total, offset, n, 1);
  file.write("solids_speed_sum", solids_speed_sum_.data(), total, offset, n, 1);
  file.close();
  return {{"duration", {duration_}}, {"pressure_sum", pressure_sum_}, {"start", {start_}},
          {"field_times", fields_.snapshotTimes()}};
}

void TimeAverages::restore(const std::map<std::string, std::vector<double>>& saved, const std::string& cell_file,
                           const std::string& id) {
  const auto value = [&](const char* name) -> const std::vector<double>& {
    const auto it = saved.find(name);
    if (it == saved.end())
      throw cfd::ConfigError("monitors.average", "set", "a checkpoint that was averaging (its loop.yaml has no " +
                                                            std::string(name) + ")");
    return it->second;
  };
  if (value("start").at(0) != start_ || value("pressure_sum").size() != pressure_sum_.size())
    throw cfd::ConfigError("monitors.average.start", std::to_string(start_),
                           "the checkpoint's " + std::to_string(value("start").at(0)) + " with the same planes");
  duration_ = value("duration").at(0);
  pressure_sum_ = value("pressure_sum");
  fields_.continueSeries(value("field_times"), {"mean_solids_fraction", "mean_gas_speed", "mean_solids_speed"}, {});
  const cfd::Hdf5Reader file(cell_file);
  if (file.textAttribute("checkpoint_id") != id)
    throw cfd::ConfigError(cell_file + ": checkpoint_id", file.textAttribute("checkpoint_id"), "the checkpoint's " + id);
  const std::vector<long long> ids = file.integers("cell_id");
  const std::vector<double> solids = file.doubles("solids_fraction_sum"), gas_speed = file.doubles("gas_speed_sum"),
                            solids_speed = file.doubles("solids_speed_sum");
  std::unordered_map<long long, std::size_t> row;
  for (std::size_t r = 0; r < ids.size(); ++r) row[ids[r]] = r;
  if (static_cast<long>(ids.size()) != mesh_.nGlobalCells())
    throw cfd::ConfigError(cell_file, std::to_string(ids.size()) + " cells", "this mesh's cells");
  for (int c = 0; c < mesh_.nOwnedCells(); ++c) {
    const std::size_t r = row.at(mesh_.globalId(c));
    solids_sum_[c] = solids[r];
    gas_speed_sum_[c] = gas_speed[r];
    solids_speed_sum_[c] = solids_speed[r];
  }
}

}  // namespace parcelflow::coupling
