// Settings of `fix ID group parcel/heat ...` and their parser (plain C++, unit-tested; throws
// ArgumentError naming the keyword, the value and what is allowed).
#pragma once

#include <string>
#include <vector>

#include "liggghts_plugins/parcel_settings.h"

namespace parcelflow::plugins {

struct ParcelHeatSettings {
  // Temperature [K] of the atoms when the fix creates the per-atom temperature `Temp`, and of atoms
  // created later; 0 when not given (then `Temp` must exist already, e.g. from fix heat/gran/conduction).
  double initial_temperature = 0.0;
  // Specific heat capacity c_p [J/(kg K)] of atom type t at entry t-1; one value per atom type.
  std::vector<double> heat_capacity;
};

// Parses the arguments after the style name, e.g. {"initial_temperature","300","heat_capacity","840"},
// for a box of `ntypes` atom types.
ParcelHeatSettings parse_parcel_heat_settings(const std::vector<std::string>& args, int ntypes);

}  // namespace parcelflow::plugins
