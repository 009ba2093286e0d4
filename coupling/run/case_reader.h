// Reads and checks a case folder's case.yaml completely (gas keys through cfd::GasConfig, the rest here)
// before any work starts: every unknown key, wrong type or out-of-range value is a cfd::ConfigError that
// names the key path, the value and what is allowed.
#pragma once

#include <string>

#include "coupling/run/coupling_settings.h"
#include "cfd/solver/gas_config.hpp"

namespace parcelflow::coupling {

struct CaseDefinition {
  std::string folder;            // the case folder, as given
  CaseSettings settings;
  cfd::GasSettings gas;
};

CaseDefinition readCase(const std::string& case_folder);

// Replaces time.end by `end` when > 0 (--end) and checks that at least one gas step follows `start`.
void applyEndTime(TimeSettings& time, double end, double start = 0.0);

// The coupling part alone, from an already parsed case.yaml (also rejects unknown top-level keys).
CaseSettings readCouplingSettings(const YAML::Node& root);

}  // namespace parcelflow::coupling
