#include "coupling/monitors/plane_averages.h"

#include <mpi.h>

#include <cmath>
#include <cstdio>

#include "cfd/base/config_error.hpp"

namespace parcelflow::coupling {

PlaneAverages::PlaneAverages(const cfd::Mesh& mesh, const std::vector<double>& heights, const char* key) : mesh_(mesh) {
  const auto& bg = mesh.background();
  for (int c = 0; c < mesh.nOwnedCells(); ++c) layer_of_cell_.push_back(bg.ijk(mesh.backgroundIndex(c))[2]);
  const double bottom = bg.origin()[2], top = bottom + bg.n()[2] * bg.spacing()[2];
  for (double z : heights) {
    // outside the mesh (or not a number) no layer, and no out-of-range conversion to int
    const int layer = z >= bottom && z < top ? static_cast<int>(std::floor((z - bottom) / bg.spacing()[2])) : -1;
    double local_volume = 0.0, volume = 0.0;
    for (int c = 0; c < mesh.nOwnedCells(); ++c)
      if (layer_of_cell_[c] == layer) local_volume += mesh.cellVolume(c);
    MPI_Allreduce(&local_volume, &volume, 1, MPI_DOUBLE, MPI_SUM, mesh.comm());
    if (volume == 0.0) {
      char text[200];
      std::snprintf(text, sizeof text, ": height %g m has no fluid cell (the mesh spans z from %g to %g m)", z,
                    bottom, top);
      throw cfd::ConfigError(key + std::string(text));
    }
    layer_of_plane_.push_back(layer);
    height_.push_back(z);
    layer_centre_.push_back(bg.origin()[2] + (layer + 0.5) * bg.spacing()[2]);
    layer_area_.push_back(volume / bg.spacing()[2]);
  }
}

std::vector<double> PlaneAverages::means(const cfd::ScalarField& field) const {
  return meansAtHeights(field, {});
}

std::vector<double> PlaneAverages::meansAtHeights(const cfd::ScalarField& field,
                                                  const cfd::VectorField& gradient) const {
  const std::size_t n = layer_of_plane_.size();
  std::vector<double> local(2 * n, 0.0), global(2 * n);
  for (int c = 0; c < mesh_.nOwnedCells(); ++c)
    for (std::size_t k = 0; k < n; ++k)
      if (layer_of_cell_[c] == layer_of_plane_[k]) {
        const double shift = gradient.empty() ? 0.0 : gradient[c][2] * (height_[k] - layer_centre_[k]);
        local[2 * k] += (field[c] + shift) * mesh_.cellVolume(c);
        local[2 * k + 1] += mesh_.cellVolume(c);
      }
  MPI_Allreduce(local.data(), global.data(), static_cast<int>(2 * n), MPI_DOUBLE, MPI_SUM, mesh_.comm());
  std::vector<double> mean(n);
  for (std::size_t k = 0; k < n; ++k) mean[k] = global[2 * k] / global[2 * k + 1];
  return mean;
}

}  // namespace parcelflow::coupling
