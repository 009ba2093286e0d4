// coupling.class_collisions: the collisions between the classes (atom types) of a size mixture that
// coarse-grained parcels do not make, added to the parcels as a force (drag/class_collision_drag.hpp).
//
// Each coupling step: the atom types that some rank's parcels have are the classes (a wall type is none).
// Every parcel deposits, for its class, its mass, momentum, volume np V_p, the moment np dp^2, its volume
// times l = D / dp and m |v|^2 on the owned cells, with the step's kernel weights, and m^2 with the weights
// squared; per cell each class gets its solids fraction, density, Sauter diameter, mean l, mass-weighted
// velocity and granular temperature (the parcels' velocity variance about that mean within the kernel's
// reach, unbiased for the few parcels a kernel holds); the classes' accelerations are gathered back with the
// same weights and each parcel gets m_p times its class's. What one class gains in a cell the others lose,
// so momentum is conserved to round-off; the parcels' own fluctuations about their class's mean are not
// touched.
#pragma once

#include <mpi.h>

#include <vector>

#include "coupling/drag/class_collision_drag.hpp"
#include "coupling/run/parcel_mesh_coupler.h"

namespace parcelflow::coupling {

class ClassCollisionExchange {
 public:
  ClassCollisionExchange(MPI_Comm comm, int types, ClassCollisionParameters parameters);

  // The force of each of this step's parcels (interleaved xyz) over a coupling interval dt; gas_fraction is
  // the (floored) a_g of the owned cells. Call after the coupler's beginStep. Collective: the cell-pairs
  // left uncorrected this step are summed over ranks and announced the first time there are any.
  void computeForces(ParcelMeshCoupler& coupler, const std::vector<double>& gas_fraction, double dt,
                     std::vector<double>& force);

  // Cell-steps of a pair of classes whose parcels exchange more than their particles (not corrected), since
  // this run (or its continuation from a checkpoint) started.
  long uncorrected() const { return uncorrected_; }

 private:
  // This step's classes: the atom types some parcel on some rank has (not the walls' type); returns how many.
  // Collective.
  int assignClasses(const ParcelBatch& parcels);

  static constexpr int kPerClass = 8;  // mass, mass v (3), volume, np dp^2, volume l, mass |v|^2
  MPI_Comm comm_;
  int types_;
  ClassCollisionDrag model_;
  long uncorrected_ = 0;
  // kept from step to step
  std::vector<double> per_parcel_, on_cells_, accel_on_cells_, at_parcels_;
  std::vector<double> squared_mass_per_class_, squared_mass_on_cells_;  // m^2, and sum w^2 m^2 per cell and class
  std::vector<int> class_of_type_;  // per atom type: its class this step, -1 if no rank's parcels have it
  std::vector<CollisionClass> classes_;
};

}  // namespace parcelflow::coupling
