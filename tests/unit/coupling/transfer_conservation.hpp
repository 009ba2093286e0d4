#pragma once
// One coupling step's transfers on a coupler whose beginStep has run, against what they must conserve: the
// parcels' volume deposited (solids fraction times the owned cells' fluid volume), the drag coefficient and
// momentum given to the gas (beta, beta u_s times volume against kappa, kappa v summed over the parcels), and
// a uniform gas field gathered exactly (a_g 0.6, u = grad p = (0.1, -0.2, 0.8)). Sums over all ranks.
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "coupling/run/parcel_mesh_coupler.h"

namespace parcelflow::coupling::test {

struct ConservationErrors {
  double volume = 0.0, kappa = 0.0, momentum = 0.0;  // relative
  double gather = 0.0;                               // largest absolute error of the gathered uniform field
};

inline double sumOverRanks(double local) {
  double total = 0.0;
  MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  return total;
}

inline ConservationErrors transferConservation(ParcelMeshCoupler& coupler, const ParcelBatch& parcels, int owned) {
  constexpr double kPi = 3.14159265358979323846;
  ConservationErrors e;
  std::vector<double> solid_fraction;
  coupler.depositSolids(solid_fraction);
  double parcel_volume = 0.0, cell_volume = 0.0;
  for (std::size_t p = 0; p < parcels.size; ++p) parcel_volume += parcels.np[p] * kPi / 6 * std::pow(parcels.dp[p], 3);
  for (int c = 0; c < owned; ++c) cell_volume += solid_fraction[c] * coupler.ownedCellVolume(c);
  e.volume = std::abs(sumOverRanks(cell_volume) / sumOverRanks(parcel_volume) - 1.0);

  const std::vector<double> gas_fraction(owned, 0.6);
  std::vector<double> velocity;
  for (int c = 0; c < owned; ++c) velocity.insert(velocity.end(), {0.1, -0.2, 0.8});
  SolidsOnCells solids;
  GasAtParcels at_parcels;
  coupler.computeDrag(gas_fraction, velocity, solids, at_parcels);
  double kappa = 0.0, kappa_v[3] = {0, 0, 0}, beta = 0.0, beta_us[3] = {0, 0, 0};
  for (std::size_t p = 0; p < parcels.size; ++p) {
    kappa += at_parcels.kappa[p];
    for (int d = 0; d < 3; ++d) kappa_v[d] += at_parcels.kappa[p] * parcels.v[3 * p + d];
    e.gather = std::max(e.gather, std::abs(at_parcels.gas_fraction[p] - 0.6));
  }
  for (int c = 0; c < owned; ++c) {
    beta += solids.beta[c] * coupler.ownedCellVolume(c);
    for (int d = 0; d < 3; ++d) beta_us[d] += solids.beta_us[3 * c + d] * coupler.ownedCellVolume(c);
  }
  e.kappa = std::abs(sumOverRanks(beta) / sumOverRanks(kappa) - 1.0);
  for (int d = 0; d < 3; ++d)
    e.momentum = std::max(e.momentum, std::abs(sumOverRanks(beta_us[d]) - sumOverRanks(kappa_v[d])) / sumOverRanks(kappa));

  coupler.gatherGas(velocity, velocity, at_parcels);
  for (std::size_t p = 0; p < parcels.size; ++p)
    for (int d = 0; d < 3; ++d)
      e.gather = std::max(e.gather, std::abs(at_parcels.gas_velocity[3 * p + d] - velocity[d]));
  return e;
}

}  // namespace parcelflow::coupling::test
