// The DEM step against the contact time of two parcels. A step of the order of the contact time ends in
// LIGGGHTS' "Lost atoms" with no hint at the cause, often in a script's own filling and settling, so
// fix parcel/implicit_drag checks it at the start of every run (init) and the coupling layer once more
// after the script (coupling/dem/contact_time_check.h prints the estimate).
//
// The contact time of two equal parcels is estimated for every atom from LIGGGHTS' own values (its
// `fix property/global` settings, already scaled by `fix parcel ... scaling linear`, and the atoms' rmass
// and radius), undamped:
//   kn given (hooke/stiffness):  t_c = pi / sqrt(kn / m_eff),                          m_eff = m/2;
//   youngsModulus (hertz):       t_c = 2.87 (m_eff^2 / (R_eff E_eff^2 v))^(1/5),       R_eff = r/2,
//                                E_eff = E / (2 (1 - nu^2)), impact speed v = 1 m/s (Johnson, Contact Mechanics).
// The shortest over all atoms must be at least kStepsPerContact DEM steps.
#pragma once

#include <stdexcept>
#include <string>

namespace LAMMPS_NS { class LAMMPS; }

namespace parcelflow::plugins {

constexpr double kStepsPerContact = 10.0;

struct ContactTime {
  bool known = false;  // false without kn or youngsModulus/poissonsRatio, or with fewer than two atoms
  double seconds = 0.0;
  double mass = 0.0, radius = 0.0;  // of the atom with the shortest contact
  int type = 0;
  const char* model = "";
};

// Collective over the LIGGGHTS communicator.
ContactTime shortest_contact_time(LAMMPS_NS::LAMMPS* lmp);

// "contact time 1.6e-3 s (pi/sqrt(kn/m_eff), two parcels of type 1, ...) = 12.9 DEM steps"
std::string describe(const ContactTime& t, double dem_step);

inline bool dem_step_too_long(const ContactTime& t, double dem_step)
{
  return t.known && dem_step > t.seconds / kStepsPerContact;
}

// Thrown on every rank by fix parcel/implicit_drag's init, i.e. before the run that would lose atoms;
// the coupling layer turns it into the user error naming time.dem_step.
class DemStepTooLong : public std::runtime_error {
 public:
  DemStepTooLong(const ContactTime& t, double dem_step, long step)
      : std::runtime_error(describe(t, dem_step)), estimate(t), dem_step(dem_step), step(step) {}
  ContactTime estimate;
  double dem_step;
  long step;  // the DEM step at which the run would have started
};

}  // namespace parcelflow::plugins
