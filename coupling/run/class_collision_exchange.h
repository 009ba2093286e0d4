// coupling.class_collisions: the collisions between the classes (atom types) of a size mixture that
// coarse-grained parcels do not make, added to the parcels as a force (drag/class_collision_drag.hpp).
//
// Each coupling step: every parcel deposits, for its type, its mass, momentum, volume np V_p, the moment
// np dp^2, its volume times l = D / dp and m |v|^2 on the owned cells, with the step's kernel weights; per
// cell each type becomes a class (solids fraction, density, Sauter diameter, mean l, mass-weighted velocity
// and granular temperature, the parcels' velocity variance about that mean within the kernel's reach); the
// classes' accelerations are gathered back with the same weights and each parcel gets m_p times its
// type's. What one type gains in a cell the others lose, so momentum is conserved to round-off; the
// parcels' own fluctuations about their type's mean are not touched.
#pragma once

#include <mpi.h>

#include <vector>

#include "class_collision_drag.hpp"
#include "parcel_mesh_coupler.h"

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
  static constexpr int kPerType = 8;  // mass, mass v (3), volume, np dp^2, volume l, mass |v|^2
  MPI_Comm comm_;
  int types_;
  ClassCollisionDrag model_;
  long uncorrected_ = 0;
  std::vector<double> per_parcel_, on_cells_, accel_on_cells_, at_parcels_;  // kept from step to step
  std::vector<CollisionClass> classes_;
};

}  // namespace parcelflow::coupling
