#include "coupling/dem/dem_parcels.h"

#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "atom.h"
#include "cfd/base/config_error.hpp"
#include "liggghts_plugins/fix_parcel.h"
#include "liggghts_plugins/fix_parcel_implicit_drag.h"
#include "liggghts_plugins/fix_parcel_reinject.h"
#include "lammps.h"
#include "modify.h"
#include "update.h"

namespace parcelflow::coupling {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The one fix of `style`; none is an error naming `why` unless why is null (an optional fix).
template <class FixType>
FixType* findFixOfStyle(LAMMPS_NS::LAMMPS* lmp, const char* style, const char* why) {
  FixType* found = nullptr;
  for (int i = 0; i < lmp->modify->nfix; ++i) {
    if (std::strcmp(lmp->modify->fix[i]->style, style) != 0) continue;
    if (found)
      throw cfd::ConfigError(std::string("the LIGGGHTS script defines more than one `fix ... ") + style +
                             "`; a coupled run needs exactly one");
    found = dynamic_cast<FixType*>(lmp->modify->fix[i]);
  }
  if (!found && why)
    throw cfd::ConfigError(std::string("the LIGGGHTS script must define `fix ID group ") + style + " ...` (" + why +
                           "); see liggghts_plugins/README.md");
  return found;
}

}  // namespace

DemParcels::DemParcels(LAMMPS_NS::LAMMPS* lmp) : lmp_(lmp) {
  parcel_ = findFixOfStyle<plugins::FixParcel>(lmp, "parcel", "it gives every parcel its dp and np");
  drag_ = findFixOfStyle<plugins::FixParcelImplicitDrag>(lmp, "parcel/implicit_drag",
                                                          "it integrates the parcels with the gas drag");
  reinject_ = findFixOfStyle<plugins::FixParcelReinject>(lmp, "parcel/reinject", nullptr);
}

ParcelBatch DemParcels::read() {
  const LAMMPS_NS::Atom* atom = lmp_->atom;
  const int n = atom->nlocal;
  x_.assign(atom->x[0], atom->x[0] + 3 * n);
  v_.assign(atom->v[0], atom->v[0] + 3 * n);
  dp_.resize(n);
  np_.resize(n);
  mass_.assign(atom->rmass, atom->rmass + n);
  type_.assign(atom->type, atom->type + n);
  id_.resize(n);
  for (int i = 0; i < n; ++i) {
    dp_[i] = parcel_->dp(i);
    np_[i] = parcel_->np(i);
    id_[i] = static_cast<long>(atom->tag[i]);
  }
  checkFinite();
  return {static_cast<std::size_t>(n), x_.data(), v_.data(), dp_.data(), np_.data(), mass_.data(), type_.data()};
}

void DemParcels::checkFinite() const {
  static const char* const kWhat[] = {"position", "velocity", "dp", "np"};
  for (std::size_t i = 0; i < id_.size(); ++i) {
    const double* values[] = {&x_[3 * i], &v_[3 * i], &dp_[i], &np_[i]};
    for (int q = 0; q < 4; ++q) {
      const int n = q < 2 ? 3 : 1;
      bool finite = true;
      for (int k = 0; k < n; ++k) finite = finite && std::isfinite(values[q][k]);
      if (finite) continue;
      char text[320];
      std::snprintf(text, sizeof text, "parcel %ld has a non-finite %s (%g, %g, %g) at DEM step %ld (LIGGGHTS time "
                    "%g s): the DEM state diverged or the script set it; the run stops", id_[i], kWhat[q],
                    values[q][0], n == 3 ? values[q][1] : 0.0, n == 3 ? values[q][2] : 0.0,
                    static_cast<long>(lmp_->update->ntimestep), lmp_->update->ntimestep * lmp_->update->dt);
      throw std::runtime_error(text);
    }
  }
}

void DemParcels::write(const GasAtParcels& gas) {
  double** d = drag_->peratom();
  using Fix = plugins::FixParcelImplicitDrag;
  const bool class_force = !gas.class_force.empty();
  for (std::size_t i = 0; i < dp_.size(); ++i) {
    const double volume = np_[i] * kPi / 6.0 * dp_[i] * dp_[i] * dp_[i];
    d[i][Fix::KAPPA] = gas.kappa[i];
    for (int k = 0; k < 3; ++k) {
      d[i][Fix::UFX + k] = gas.gas_velocity[3 * i + k];
      // the explicit force of the coupling interval: the pressure force and the missing class collisions
      d[i][Fix::FPX + k] = -volume * gas.grad_p[3 * i + k] + (class_force ? gas.class_force[3 * i + k] : 0.0);
    }
  }
}

void DemParcels::keepForcesForRestart() { drag_->keepForcesForRestart(); }

long DemParcels::globalCount() const {
  const long pending = reinject_ ? std::lround(reinject_->counter(plugins::FixParcelReinject::PENDING_N)) : 0;
  return static_cast<long>(lmp_->atom->natoms) + pending;
}

int DemParcels::ntypes() const { return lmp_->atom->ntypes; }

bool DemParcels::keepsShearStress() const { return parcel_->settings().shear_stress_restitution > 0.0; }

std::vector<double> DemParcels::meanHeightPerType() const {
  const LAMMPS_NS::Atom* atom = lmp_->atom;
  const int ntypes = atom->ntypes;
  std::vector<double> local(2 * ntypes, 0.0), global(2 * ntypes);
  for (int i = 0; i < atom->nlocal; ++i) {
    const int t = atom->type[i] - 1;
    local[2 * t] += atom->rmass[i] * atom->x[i][2];
    local[2 * t + 1] += atom->rmass[i];
  }
  MPI_Allreduce(local.data(), global.data(), 2 * ntypes, MPI_DOUBLE, MPI_SUM, lmp_->world);
  std::vector<double> mean(ntypes);
  for (int t = 0; t < ntypes; ++t)
    mean[t] = global[2 * t + 1] > 0.0 ? global[2 * t] / global[2 * t + 1] : std::numeric_limits<double>::quiet_NaN();
  return mean;
}

double DemParcels::totalMass() const {
  double local = 0.0, global = 0.0;
  for (int i = 0; i < lmp_->atom->nlocal; ++i) local += lmp_->atom->rmass[i];
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, lmp_->world);
  return global;
}

double DemParcels::buoyantWeightAbove(double z, double gas_density, double gravity) const {
  const LAMMPS_NS::Atom* atom = lmp_->atom;
  double local = 0.0, global = 0.0;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (atom->x[i][2] <= z) continue;
    const double r = atom->radius[i];
    local += (atom->rmass[i] - gas_density * 4.0 / 3.0 * kPi * r * r * r) * gravity;
  }
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, lmp_->world);
  return global;
}

}  // namespace parcelflow::coupling
