#include "register_styles.h"

#include "lammps.h"
#include "modify.h"

namespace parcelflow::plugins {

void register_styles(LAMMPS_NS::LAMMPS* /*lmp*/) {}

}  // namespace parcelflow::plugins
