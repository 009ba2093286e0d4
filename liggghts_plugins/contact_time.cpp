#include "liggghts_plugins/contact_time.h"

#include <mpi.h>

#include <cmath>
#include <cstdio>

#include "atom.h"
#include "fix_property_global.h"
#include "lammps.h"
#include "modify.h"

namespace parcelflow::plugins {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kImpactSpeed = 1.0;  // m/s, for the Hertz estimate

LAMMPS_NS::FixPropertyGlobal* property(LAMMPS_NS::LAMMPS* lmp, const char* name, const char* kind, int n1, int n2)
{
  return static_cast<LAMMPS_NS::FixPropertyGlobal*>(
      lmp->modify->find_fix_property(name, "property/global", kind, n1, n2, "parcelflow contact time check", false));
}

}  // namespace

ContactTime shortest_contact_time(LAMMPS_NS::LAMMPS* lmp)
{
  const LAMMPS_NS::Atom* atom = lmp->atom;
  const int ntypes = atom->ntypes;
  LAMMPS_NS::FixPropertyGlobal* kn = property(lmp, "kn", "peratomtypepair", ntypes, ntypes);
  LAMMPS_NS::FixPropertyGlobal* young = property(lmp, "youngsModulus", "peratomtype", ntypes, 0);
  LAMMPS_NS::FixPropertyGlobal* poisson = property(lmp, "poissonsRatio", "peratomtype", ntypes, 0);
  ContactTime result;
  // A single atom has no partner (the estimate is for two parcels; walls give m_eff = m, a longer contact).
  if ((!kn && !(young && poisson)) || atom->natoms < 2) return result;
  struct { double tc; int rank; } mine{INFINITY, 0}, shortest{};
  MPI_Comm_rank(lmp->world, &mine.rank);
  double parcel[3] = {0.0, 0.0, 0.0};  // mass, radius, type of the atom with the shortest contact
  for (int i = 0; i < atom->nlocal; ++i) {
    const int t = atom->type[i] - 1;
    const double m_eff = atom->rmass[i] / 2.0;
    double tc = 0.0;
    if (kn) {
      tc = kPi / std::sqrt(kn->compute_array(t, t) / m_eff);
    } else {
      const double nu = poisson->compute_vector(t);
      const double e_eff = young->compute_vector(t) / (2.0 * (1.0 - nu * nu));
      tc = 2.87 * std::pow(m_eff * m_eff / (atom->radius[i] / 2.0 * e_eff * e_eff * kImpactSpeed), 0.2);
    }
    if (tc < mine.tc) {
      mine.tc = tc;
      parcel[0] = atom->rmass[i];
      parcel[1] = atom->radius[i];
      parcel[2] = t + 1;
    }
  }
  MPI_Allreduce(&mine, &shortest, 1, MPI_DOUBLE_INT, MPI_MINLOC, lmp->world);
  MPI_Bcast(parcel, 3, MPI_DOUBLE, shortest.rank, lmp->world);
  result.known = true;
  result.seconds = shortest.tc;
  result.mass = parcel[0];
  result.radius = parcel[1];
  result.type = static_cast<int>(parcel[2]);
  result.model = kn ? "pi/sqrt(kn/m_eff)" : "Hertz at 1 m/s";
  return result;
}

std::string describe(const ContactTime& t, double dem_step)
{
  char text[400];
  std::snprintf(text, sizeof text,
                "contact time %.3g s (%s, two parcels of type %d, mass %.3g kg, radius %.3g m) = %.1f DEM steps",
                t.seconds, t.model, t.type, t.mass, t.radius, t.seconds / dem_step);
  return text;
}

}  // namespace parcelflow::plugins
