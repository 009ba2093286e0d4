// fix ID group parcel/heat heat_capacity c_1 ... c_N [initial_temperature T0]
//
// The temperature of gas-coupled parcels. Each parcel carries the gas temperature at its position T_g,
// its gas-particle conductance H = np h pi d_p^2 [W/K] and a heat source S [W] (columns set by the
// coupling layer between DEM runs; they migrate with atoms and are written to restart files). Every DEM
// step, after LIGGGHTS' own heat integration if there is one, the fix advances
//     M c dT/dt = H (T_g - T) + S + Q
// by implicit Euler (parcel_heat_step.hpp): stable and free of overshoot for any dt H/(M c). The
// temperature is LIGGGHTS' per-atom `Temp` (fix property/atom), so fix heat/gran/conduction, defined
// BEFORE this fix, adds the contact conduction Q. Per-atom output (dump f_ID[1..4]): T_g, H, S and the heat
// received from the gas, sum dt (H (T_g - T_new) + S), since the coupling layer last zeroed it [J]; the
// temperature is f_Temp. The global scalar is the group's heat content sum M c T [J].
// Documentation: fix_parcel_heat.md.
#pragma once

#include <vector>

#include "liggghts_plugins/parcel_heat_settings.hpp"
#include "liggghts_plugins/per_atom_columns_fix.h"

namespace LAMMPS_NS {
class FixPropertyAtom;
}

namespace parcelflow::plugins {

class FixParcelHeat : public PerAtomColumnsFix {
 public:
  enum Column { GAS_TEMPERATURE = 0, CONDUCTANCE, SOURCE, HEAT_RECEIVED, NCOLUMNS };

  FixParcelHeat(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);

  int setmask() override;
  void post_create() override;
  void init() override;
  void setup(int vflag) override;
  void final_integrate() override;
  double compute_scalar() override;

  void set_arrays(int i) override;  // new atoms exchange no heat until the coupling sets their columns

  // Coupling interface: local atoms 0..nlocal-1; re-fetch after every run (atoms move and reorder).
  double* temperature();  // LIGGGHTS' per-atom Temp [K]
  double heat_capacity(int i) const;  // M c of local atom i [J/K]

 private:
  [[noreturn]] void fail(const std::string& msg);
  void check_conduction_fix();

  ParcelHeatSettings settings_;
  LAMMPS_NS::FixPropertyAtom* temp_ = nullptr;
};

}  // namespace parcelflow::plugins
