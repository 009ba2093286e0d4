// Registers parcelflow's LIGGGHTS styles into a LIGGGHTS instance (Debian's LIGGGHTS 3.8 has no plugin
// API). Call it after the instance is created and again after every `clear`, which re-creates the
// registries; the parcelflow program does both through its post_create hook.
#pragma once

namespace LAMMPS_NS { class LAMMPS; }

namespace parcelflow::plugins {

void register_styles(LAMMPS_NS::LAMMPS* lmp);

}  // namespace parcelflow::plugins
