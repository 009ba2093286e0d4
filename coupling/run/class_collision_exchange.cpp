#include "class_collision_exchange.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cfd/internal_error.hpp"

namespace parcelflow::coupling {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

ClassCollisionExchange::ClassCollisionExchange(MPI_Comm comm, int types, ClassCollisionParameters parameters)
    : comm_(comm), types_(types), model_(parameters), classes_(types) {}

void ClassCollisionExchange::computeForces(ParcelMeshCoupler& coupler, const std::vector<double>& gas_fraction,
                                           double dt, std::vector<double>& force) {
  const ParcelBatch& parcels = coupler.parcels();
  PARCELFLOW_ASSERT(parcels.size == 0 || (parcels.mass && parcels.type), "class collisions need masses and types");
  const int width = kPerType * types_;
  per_parcel_.assign(parcels.size * width, 0.0);
  for (std::size_t p = 0; p < parcels.size; ++p) {
    const int t = parcels.type[p] - 1;
    PARCELFLOW_ASSERT(t >= 0 && t < types_, "a parcel's atom type is outside 1..ntypes");
    double* q = per_parcel_.data() + width * p + kPerType * t;
    const double m = parcels.mass[p], dp = parcels.dp[p], np = parcels.np[p];
    const double volume = np * kPi / 6.0 * dp * dp * dp;
    q[0] = m;
    for (int d = 0; d < 3; ++d) q[1 + d] = m * parcels.v[3 * p + d];
    q[4] = volume;
    q[5] = np * dp * dp;
    q[6] = volume * std::cbrt(np);  // l = D / dp = np^(1/3) in both parcel modes
    for (int d = 0; d < 3; ++d) q[7] += m * parcels.v[3 * p + d] * parcels.v[3 * p + d];
  }
  coupler.depositToOwners(per_parcel_, width, on_cells_);
  const int cells = coupler.ownedCells();
  accel_on_cells_.assign(static_cast<std::size_t>(cells) * 3 * types_, 0.0);
  long uncorrected = 0;
  for (int c = 0; c < cells; ++c) {
    const double cell_volume = coupler.ownedCellVolume(c);
    for (int t = 0; t < types_; ++t) {
      const double* q = on_cells_.data() + static_cast<std::size_t>(width) * c + kPerType * t;
      CollisionClass& k = classes_[t];
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
      // the spread of the parcels about their class's mean, where the kernel reaches (0 for one parcel)
      k.temperature = std::max(0.0, (q[7] / q[0] - mean_square) / 3.0);
    }
    uncorrected += model_.accelerations(classes_.data(), classes_.size(), gas_fraction[c], dt,
                                        accel_on_cells_.data() + static_cast<std::size_t>(c) * 3 * types_);
  }
  // Orphans (no fluid cell in reach) get no force, as they get no drag.
  coupler.gatherFromOwned(accel_on_cells_, 3 * types_, 0.0, at_parcels_);
  force.resize(3 * parcels.size);
  for (std::size_t p = 0; p < parcels.size; ++p) {
    const double* a = at_parcels_.data() + 3 * types_ * p + 3 * (parcels.type[p] - 1);
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

}  // namespace parcelflow::coupling
