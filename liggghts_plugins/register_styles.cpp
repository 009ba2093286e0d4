#include "liggghts_plugins/register_styles.h"

#include "liggghts_plugins/fix_map_access.h"
#include "liggghts_plugins/fix_parcel.h"
#include "liggghts_plugins/fix_parcel_heat.hpp"
#include "liggghts_plugins/fix_parcel_implicit_drag.h"
#include "liggghts_plugins/fix_parcel_reinject.h"
#include "lammps.h"

namespace parcelflow::plugins {
namespace {

template <class T>
LAMMPS_NS::Fix* create_fix(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg)
{
  return new T(lmp, narg, arg);
}

}  // namespace

void register_styles(LAMMPS_NS::LAMMPS* lmp)
{
  auto& fixes = fix_map(lmp);
  fixes["parcel"] = &create_fix<FixParcel>;
  fixes["parcel/implicit_drag"] = &create_fix<FixParcelImplicitDrag>;
  fixes["parcel/reinject"] = &create_fix<FixParcelReinject>;
  fixes["parcel/heat"] = &create_fix<FixParcelHeat>;
}

}  // namespace parcelflow::plugins
