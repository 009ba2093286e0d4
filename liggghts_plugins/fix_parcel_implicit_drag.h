// fix ID group parcel/implicit_drag
//
// Time integrator for gas-coupled parcels (replaces nve/sphere for them; DESIGN section 4). Each parcel
// carries an implicit drag coefficient kappa [kg/s], the gas velocity u_f at its position and the
// pressure-gradient force f_p = -np V_p grad p [N], set by the coupling layer between DEM runs; they
// migrate with atoms and are written to restart files. Each velocity-Verlet half step of length h is
//     v <- (v + h (f + f_p)/m + h (kappa/m) u_f) / (1 + h kappa/m),
// implicit in the drag: stable for any kappa dt/m, so fines whose response time is shorter than the DEM
// step stay stable, and the steady state is exactly v = u_f + (f + f_p)/kappa. Rotation as nve/sphere.
// Per-atom output (dump f_ID[1..7]): kappa, u_f (3), f_p (3).
#pragma once

#include "per_atom_columns_fix.h"

namespace parcelflow::plugins {

class FixParcelImplicitDrag : public PerAtomColumnsFix {
 public:
  enum Column { KAPPA = 0, UFX, UFY, UFZ, FPX, FPY, FPZ, NCOLUMNS };

  FixParcelImplicitDrag(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);

  int setmask() override;
  void init() override;
  void initial_integrate(int vflag) override;
  void final_integrate() override;
  void reset_dt() override;

  void set_arrays(int i) override;  // new atoms feel no gas until the coupling sets their columns

 private:
  void halfStep(bool move);

  double dtv_ = 0.0, dtf_ = 0.0;
};

}  // namespace parcelflow::plugins
