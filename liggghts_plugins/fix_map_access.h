// Access to LIGGGHTS' private fix-style registry Modify::fix_map (see fix_map_access.cpp for why and how).
#pragma once

#include <map>
#include <string>

namespace LAMMPS_NS {
class LAMMPS;
class Fix;
}  // namespace LAMMPS_NS

namespace parcelflow::plugins {

using FixCreator = LAMMPS_NS::Fix* (*)(LAMMPS_NS::LAMMPS*, int, char**);

// The map from fix style name to creator function owned by lmp->modify (valid until the next `clear`).
std::map<std::string, FixCreator>& fix_map(LAMMPS_NS::LAMMPS* lmp);

}  // namespace parcelflow::plugins
