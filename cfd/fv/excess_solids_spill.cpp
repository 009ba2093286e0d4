#include "cfd/fv/excess_solids_spill.hpp"

#include <mpi.h>

#include <algorithm>
#include <string>

#include "cfd/base/internal_error.hpp"

namespace parcelflow::cfd {

SpillStats spillExcessSolids(const Mesh& mesh, std::vector<double>& owned, double maxSolids, int passes) {
  const int nOwned = mesh.nOwnedCells(), nLocal = mesh.nLocalCells();
  PARCELFLOW_ASSERT(static_cast<int>(owned.size()) == nOwned, "spill: field is not on the owned cells");
  ScalarField excess(nLocal, 0.0), room(nLocal, 0.0), around(nLocal, 0.0), gain(nOwned, 0.0);
  SpillStats stats;
  for (int pass = 0; pass < passes; ++pass) {
    int anyExcess = 0;
    for (int c = 0; c < nOwned; ++c) {
      const double v = mesh.cellVolume(c);
      excess[c] = std::max(0.0, owned[c] - maxSolids) * v;
      room[c] = std::max(0.0, maxSolids - owned[c]) * v;
      if (excess[c] > 1e-12 * v) anyExcess = 1;
    }
    MPI_Allreduce(MPI_IN_PLACE, &anyExcess, 1, MPI_INT, MPI_MAX, mesh.comm());
    if (!anyExcess) break;
    stats.passes = pass + 1;
    mesh.exchange(excess);
    mesh.exchange(room);
    std::fill(around.begin(), around.end(), 0.0);
    for (int f = 0; f < mesh.nInternalFaces(); ++f) {
      const int o = mesh.faceOwner(f), n = mesh.faceNeighbour(f);
      if (o < nOwned) around[o] += room[n];
      if (n < nOwned) around[n] += room[o];
    }
    mesh.exchange(around);
    std::fill(gain.begin(), gain.end(), 0.0);
    // the share of its room that a giver fills in each neighbour
    const auto share = [&](int giver) {
      return around[giver] > 0.0 ? std::min(1.0, excess[giver] / around[giver]) : 0.0;
    };
    for (int f = 0; f < mesh.nInternalFaces(); ++f) {
      const int o = mesh.faceOwner(f), n = mesh.faceNeighbour(f);
      if (o < nOwned && excess[n] > 0.0) gain[o] += room[o] * share(n);
      if (n < nOwned && excess[o] > 0.0) gain[n] += room[n] * share(o);
    }
    for (int c = 0; c < nOwned; ++c) {
      const double given = std::min(excess[c], around[c]);
      if (given > 0.0) ++stats.cells;
      owned[c] += (gain[c] - given) / mesh.cellVolume(c);
    }
  }
  return stats;
}

}  // namespace parcelflow::cfd
