#include "liggghts_plugins/fix_parcel_implicit_drag.h"

#include "atom.h"
#include "comm.h"
#include "liggghts_plugins/contact_time.h"
#include "error.h"
#include "force.h"
#include "modify.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace LAMMPS_NS::FixConst;

namespace parcelflow::plugins {

namespace {
constexpr double kSphereInertia = 0.4;  // I = 0.4 m r^2
}

FixParcelImplicitDrag::FixParcelImplicitDrag(LAMMPS* lmp, int narg, char** arg)
    : PerAtomColumnsFix(lmp, narg, arg, NCOLUMNS)
{
  if (narg != 3)
    error->all(FLERR, "fix parcel/implicit_drag takes no arguments (usage: fix ID group parcel/implicit_drag); "
                      "the coupling layer sets kappa, u_f and f_p");
  time_integrate = 1;
  for (int i = 0; i < atom->nlocal; ++i) set_arrays(i);
}

int FixParcelImplicitDrag::setmask() { return INITIAL_INTEGRATE | FINAL_INTEGRATE; }

void FixParcelImplicitDrag::init()
{
  if (!atom->sphere_flag || !atom->rmass_flag)
    error->all(FLERR, "fix parcel/implicit_drag needs spheres with per-atom mass (atom_style granular)");
  reset_dt();
  // before every run, the script's filling and settling included: a step near the contact time loses atoms
  const ContactTime contact = shortest_contact_time(lmp);
  if (dem_step_too_long(contact, update->dt))
    throw DemStepTooLong(contact, update->dt, static_cast<long>(update->ntimestep));
}

void FixParcelImplicitDrag::reset_dt()
{
  dtv_ = update->dt;
  dtf_ = 0.5 * update->dt * force->ftm2v;
}

void FixParcelImplicitDrag::halfStep(bool move)
{
  double** x = atom->x;
  double** v = atom->v;
  double** f = atom->f;
  double** omega = atom->omega;
  double** torque = atom->torque;
  const double* radius = atom->radius;
  const double* rmass = atom->rmass;
  const int* mask = atom->mask;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    const double* d = data_[i];
    const double h_over_m = dtf_ / rmass[i];
    const double implicit = 1.0 / (1.0 + h_over_m * d[KAPPA]);
    for (int k = 0; k < 3; ++k)
      v[i][k] = (v[i][k] + h_over_m * (f[i][k] + d[FPX + k] + d[KAPPA] * d[UFX + k])) * implicit;
    if (move)
      for (int k = 0; k < 3; ++k) x[i][k] += dtv_ * v[i][k];
    const double h_over_inertia = dtf_ / (kSphereInertia * radius[i] * radius[i] * rmass[i]);
    for (int k = 0; k < 3; ++k) omega[i][k] += h_over_inertia * torque[i][k];
  }
}

void FixParcelImplicitDrag::keepForcesForRestart()
{
  for (int i = 0; i < atom->nlocal; ++i) {
    for (int k = 0; k < 3; ++k) {
      data_[i][KEPT_FX + k] = atom->f[i][k];
      data_[i][KEPT_TX + k] = atom->torque[i][k];
    }
    data_[i][FORCES_KEPT] = 1.0;
  }
}

void FixParcelImplicitDrag::setup(int)
{
  int kept = 0;
  for (int i = 0; i < atom->nlocal; ++i) kept = kept || data_[i][FORCES_KEPT] != 0.0;
  int any_kept = 0;
  MPI_Allreduce(&kept, &any_kept, 1, MPI_INT, MPI_MAX, world);
  if (!any_kept) return;
  // A fix after this one that adds forces in its setup would add them a second time on top of the kept
  // forces: then the restart keeps LIGGGHTS' recomputed forces (and is not exact).
  const int me = modify->find_fix(id);
  for (int j = me + 1; j < modify->nfix; ++j)
    if (modify->fmask[j] & POST_FORCE) {
      if (comm->me == 0)
        error->warning(FLERR, "fix parcel/implicit_drag: a force fix is defined after it; the restart recomputes "
                              "the first step's forces instead of using the kept ones (not exact)");
      any_kept = 0;
    }
  for (int i = 0; i < atom->nlocal; ++i) {
    if (any_kept && data_[i][FORCES_KEPT] != 0.0)
      for (int k = 0; k < 3; ++k) {
        atom->f[i][k] = data_[i][KEPT_FX + k];
        atom->torque[i][k] = data_[i][KEPT_TX + k];
      }
    data_[i][FORCES_KEPT] = 0.0;
  }
}

void FixParcelImplicitDrag::initial_integrate(int) { halfStep(true); }

void FixParcelImplicitDrag::final_integrate() { halfStep(false); }

void FixParcelImplicitDrag::set_arrays(int i)
{
  for (int c = 0; c < NCOLUMNS; ++c) data_[i][c] = 0.0;
}

}  // namespace parcelflow::plugins
