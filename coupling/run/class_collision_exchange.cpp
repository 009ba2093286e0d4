#include "coupling/run/class_collision_exchange.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cfd/base/internal_error.hpp"

namespace parcelflow::coupling {

namespace {
constexpr double kPi = 3.14159265358979323846;
// n - 1 below this: one parcel (n = 1 but for round-off), whose spread is round-off too
constexpr double kOneParcel = 1e-9;
}

ClassCollisionExchange::ClassCollisionExchange(MPI_Comm comm, int types, ClassCollisionParameters parameters)
    : comm_(comm), types_(types), model_(parameters), classes_(types) {}

void ClassCollisionExchange::computeForces(ParcelMeshCoupler& coupler, const std::vector<double>& gas_fraction,
                                           double dt, std::vector<double>& force) {
  const ParcelBatch& parcels = coupler.parcels();
  PARCELFLOW_ASSERT(parcels.size == 0 || (parcels.mass && parcels.type), "class collisions need masses and types");
  const int classes = assignClasses(parcels);
  const int width = kPerClass * classes;
  per_parcel_.assign(parcels.size * width, 0.0);
  squared_mass_per_class_.assign(parcels.size * classes, 0.0);
  for (std::size_t p = 0; p < parcels.size; ++p) {
    const int slot = class_of_type_[parcels.type[p] - 1];
    double* q = per_parcel_.data() + width * p + kPerClass * slot;
    const double m = parcels.mass[p], dp = parcels.dp[p], np = parcels.np[p];
    const double volume = np * kPi / 6.0 * dp * dp * dp;
    q[0] = m;
    squared_mass_per_class_[classes * p + slot] = m * m;
    for (int d = 0; d < 3; ++d) q[1 + d] = m * parcels.v[3 * p + d];
    q[4] = volume;
    q[5] = np * dp * dp;
    q[6] = volume * std::cbrt(np);  // l = D / dp = np^(1/3) in both parcel modes
    for (int d = 0; d < 3; ++d) q[7] += m * parcels.v[3 * p + d] * parcels.v[3 * p + d];
  }
  coupler.depositToOwners(per_parcel_, width, on_cells_);
  coupler.depositSquaredWeightsToOwners(squared_mass_per_class_, classes, squared_mass_on_cells_);
  const int cells = coupler.ownedCells();
  accel_on_cells_.assign(static_cast<std::size_t>(cells) * 3 * classes, 0.0);
  long uncorrected = 0;
  for (int c = 0; c < cells; ++c) {
    const double cell_volume = coupler.ownedCellVolume(c);
    for (int slot = 0; slot < classes; ++slot) {
      const double* q = on_cells_.data() + static_cast<std::size_t>(width) * c + kPerClass * slot;
      CollisionClass& k = classes_[slot];
      k.solid_fraction = q[0] > 0.0 && q[4] > 0.0 ? q[4] / cell_volume : 0.0;
      if (k.solid_fraction == 0.0) continue;
      k.density = q[0] / q[4];
      k.diameter = 6.0 / kPi * q[4] / q[5];
      k.parcel_diameter = k.diameter * q[6] / q[4];
      double mean_square = 0.0;
      for (int d = 0; d < 3; ++d) {
        k.velocity[d] = q[1 + d] / q[0];
        mean_square += k.velocity[d] * k.velocity[d];
      }
      // The spread of the parcels about their class's mean where the kernel reaches: the weighted variance,
      // times n / (n - 1) for its n = (sum w m)^2 / sum (w m)^2 parcels, since it is taken about their own
      // mean (unbiased; a class of about 3 parcels, as the np 8 Goldschmidt bed's large one, otherwise shows
      // two thirds of its spread). One parcel shows none: 0 (the max only drops round-off below 0).
      const double squared_mass = squared_mass_on_cells_[static_cast<std::size_t>(classes) * c + slot];
      const double excess = q[0] * q[0] - squared_mass;  // (sum w m)^2 (1 - 1/n)
      const double spread = std::max(0.0, (q[7] / q[0] - mean_square) / 3.0);
      k.temperature = excess > kOneParcel * q[0] * q[0] ? spread * q[0] * q[0] / excess : 0.0;
    }
    uncorrected += model_.accelerations(classes_.data(), classes, gas_fraction[c], dt,
                                        accel_on_cells_.data() + static_cast<std::size_t>(c) * 3 * classes);
  }
  // Orphans (no fluid cell in reach) get no force, as they get no drag.
  coupler.gatherFromOwned(accel_on_cells_, 3 * classes, 0.0, at_parcels_);
  force.resize(3 * parcels.size);
  for (std::size_t p = 0; p < parcels.size; ++p) {
    const double* a = at_parcels_.data() + 3 * classes * p + 3 * class_of_type_[parcels.type[p] - 1];
    for (int d = 0; d < 3; ++d) force[3 * p + d] = parcels.mass[p] * a[d];
  }
  long step_total = 0;
  MPI_Allreduce(&uncorrected, &step_total, 1, MPI_LONG, MPI_SUM, comm_);
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  if (step_total > 0 && uncorrected_ == 0 && rank == 0)
    std::printf("parcelflow: warning: coupling.class_collisions: in %ld cells two classes of parcels exchange more "
                "momentum by collisions than their particles would (a small class under a much larger parcel "
                "diameter); nothing is taken away there, and these cell-steps are counted to the end of the run\n",
                step_total);
  uncorrected_ += step_total;
}

int ClassCollisionExchange::assignClasses(const ParcelBatch& parcels) {
  class_of_type_.assign(types_, 0);  // first whether this rank has a parcel of the type, then its class
  for (std::size_t p = 0; p < parcels.size; ++p) {
    const int t = parcels.type[p] - 1;
    PARCELFLOW_ASSERT(t >= 0 && t < types_, "a parcel's atom type is outside 1..ntypes");
    class_of_type_[t] = 1;
  }
  MPI_Allreduce(MPI_IN_PLACE, class_of_type_.data(), types_, MPI_INT, MPI_MAX, comm_);
  int classes = 0;
  for (int& held : class_of_type_) held = held ? classes++ : -1;
  return classes;
}

}  // namespace parcelflow::coupling
