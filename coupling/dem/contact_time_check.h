// The DEM step against the contact time (liggghts_plugins/contact_time.h has the estimate): checked by
// fix parcel/implicit_drag at the start of every run of the case's script, and here once after it.
#pragma once

#include <string>

#include "liggghts_plugins/contact_time.h"
#include "cfd/base/config_error.hpp"

namespace LAMMPS_NS { class LAMMPS; }

namespace parcelflow::coupling {

using plugins::kStepsPerContact;

// The user error naming `key` (time.dem_step, or the script's timestep), the estimate and the limit; `when`
// says where it was found.
cfd::ConfigError demStepError(const std::string& key, const plugins::ContactTime& estimate, double dem_step,
                              const std::string& when);

// Throws demStepError; returns a line describing the estimate ("" when the contact model has neither kn nor
// youngsModulus, or with one parcel). Collective.
std::string checkContactTime(LAMMPS_NS::LAMMPS* lmp, double dem_step);

}  // namespace parcelflow::coupling
