// The coupling layer's only window into LIGGGHTS' parcels: reads positions, velocities, dp and np of the
// local parcels after each DEM advance (LIGGGHTS moves and reorders its arrays on every run), and writes
// the implicit drag coefficient, gas velocity and the explicit forces (pressure gradient, missing class
// collisions) into the integrator fix.
#pragma once

#include <string>
#include <vector>

#include "coupling/run/parcel_mesh_coupler.h"

namespace LAMMPS_NS { class LAMMPS; }
namespace parcelflow::plugins { class FixParcel; class FixParcelImplicitDrag; class FixParcelReinject; }

namespace parcelflow::coupling {

class DemParcels {
 public:
  // Throws cfd::ConfigError when the script lacks `fix ... parcel` or `fix ... parcel/implicit_drag`.
  explicit DemParcels(LAMMPS_NS::LAMMPS* lmp);

  // Copies the local parcels; the batch points into this object and stays valid until the next read.
  // A non-finite position, velocity, dp or np throws std::runtime_error naming the parcel id, the value
  // and the DEM step (only the rank that holds the parcel knows: it stops all ranks).
  ParcelBatch read();
  // Sets kappa, u_f and the explicit force -np V_p grad p (+ gas.class_force if set) of the parcels of the last
  // read().
  void write(const GasAtParcels& gas);
  // Atom types and ids of the parcels of the last read() (for parcel output).
  const std::vector<int>& types() const { return type_; }
  const std::vector<long>& ids() const { return id_; }
  // The forces the next DEM step starts from go into the next restart file and back at the next setup.
  void keepForcesForRestart();

  // Parcels in the run: LIGGGHTS' atoms and those `fix parcel/reinject` holds pending.
  long globalCount() const;
  // The script's `fix parcel/reinject`, or null.
  const plugins::FixParcelReinject* reinjection() const { return reinject_; }
  int ntypes() const;
  // fix parcel's shear_stress is on (parcel-parcel restitution lowered to keep the particles' shear stress)
  bool keepsShearStress() const;
  // Mass-weighted mean height of each atom type (index type-1); NaN for an empty type. Collective.
  std::vector<double> meanHeightPerType() const;
  double totalMass() const;  // collective
  // Weight minus buoyancy, sum of (m - rho_g V) g over parcels with centre above z [N]. Collective.
  double buoyantWeightAbove(double z, double gas_density, double gravity) const;

 private:
  void checkFinite() const;

  LAMMPS_NS::LAMMPS* lmp_;
  plugins::FixParcel* parcel_ = nullptr;
  plugins::FixParcelImplicitDrag* drag_ = nullptr;
  plugins::FixParcelReinject* reinject_ = nullptr;
  std::vector<double> x_, v_, dp_, np_, mass_;
  std::vector<int> type_;
  std::vector<long> id_;
};

}  // namespace parcelflow::coupling
