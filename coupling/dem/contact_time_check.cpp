#include "coupling/dem/contact_time_check.h"

#include <cstdio>

namespace parcelflow::coupling {

cfd::ConfigError demStepError(const std::string& key, const plugins::ContactTime& estimate, double dem_step,
                              const std::string& when)
{
  char value[640], allowed[160];
  std::snprintf(value, sizeof value, "%g s against the %s, %s", dem_step, plugins::describe(estimate, dem_step).c_str(),
                when.c_str());
  std::snprintf(allowed, sizeof allowed, "at most t_c/%.0f = %.3g s (at least %.0f DEM steps per contact)",
                kStepsPerContact, estimate.seconds / kStepsPerContact, kStepsPerContact);
  return cfd::ConfigError(key, value, allowed);
}

std::string checkContactTime(LAMMPS_NS::LAMMPS* lmp, double dem_step)
{
  const plugins::ContactTime estimate = plugins::shortest_contact_time(lmp);
  if (plugins::dem_step_too_long(estimate, dem_step)) throw demStepError("time.dem_step", estimate, dem_step, "after the script");
  return estimate.known ? plugins::describe(estimate, dem_step) : "";
}

}  // namespace parcelflow::coupling
