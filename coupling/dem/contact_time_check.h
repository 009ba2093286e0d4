// The DEM step against the contact time, checked after the case's script ran (a step of the order of the
// contact time ends in LIGGGHTS' "Lost atoms" with no hint at the cause). The contact time of two equal
// parcels is estimated for every parcel from LIGGGHTS' own values (its `fix property/global` settings,
// already scaled by `fix parcel ... scaling linear`, and the atoms' rmass and radius), undamped:
//   kn given (hooke/stiffness):  t_c = pi / sqrt(kn / m_eff),                          m_eff = m/2;
//   youngsModulus (hertz):       t_c = 2.87 (m_eff^2 / (R_eff E_eff^2 v))^(1/5),       R_eff = r/2,
//                                E_eff = E / (2 (1 - nu^2)), impact speed v = 1 m/s (Johnson, Contact Mechanics).
// The shortest over all parcels must be at least kStepsPerContact DEM steps. With a single parcel there is
// no such contact and no check.
#pragma once

#include <string>

namespace LAMMPS_NS { class LAMMPS; }

namespace parcelflow::coupling {

constexpr double kStepsPerContact = 10.0;

// Throws cfd::ConfigError naming time.dem_step, the estimate and the limit; returns a line describing the
// estimate ("" when the contact model has neither kn nor youngsModulus, or with one parcel). Collective.
std::string checkContactTime(LAMMPS_NS::LAMMPS* lmp, double dem_step);

}  // namespace parcelflow::coupling
