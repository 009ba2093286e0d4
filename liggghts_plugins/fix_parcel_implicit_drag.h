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
//
// Exact restarts: `run N pre no` starts a chunk from the forces of the previous chunk's last step, which were
// computed with the half-step velocities; the setup of the first run after read_restart would recompute them
// from the full-step ones (LIGGGHTS' read_restart documentation: granular pair styles "will not restart
// exactly"). keepForcesForRestart() copies f and torque into columns 8-14 just before write_restart, and
// setup() of the next run puts them back (in the restarted run and in the run that wrote the file, which
// must set up again after write_restart), so both take the same next step.
#pragma once

#include "liggghts_plugins/per_atom_columns_fix.h"

namespace parcelflow::plugins {

class FixParcelImplicitDrag : public PerAtomColumnsFix {
 public:
  enum Column { KAPPA = 0, UFX, UFY, UFZ, FPX, FPY, FPZ, KEPT_FX, KEPT_FY, KEPT_FZ, KEPT_TX, KEPT_TY, KEPT_TZ,
                FORCES_KEPT, NCOLUMNS };

  FixParcelImplicitDrag(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);

  int setmask() override;
  void init() override;
  void initial_integrate(int vflag) override;
  void final_integrate() override;
  void reset_dt() override;
  void setup(int vflag) override;

  // Copies f and torque into the kept columns (right before write_restart); the next setup puts them back.
  void keepForcesForRestart();

  void set_arrays(int i) override;  // new atoms feel no gas until the coupling sets their columns

 private:
  void halfStep(bool move);

  double dtv_ = 0.0, dtf_ = 0.0;
};

}  // namespace parcelflow::plugins
