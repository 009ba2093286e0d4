#include "coupling/run/side_walls.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace parcelflow::coupling {

double sideWallAreaPerVolume(const cfd::Mesh& mesh, const std::vector<cfd::BoundarySettings>& boundaries,
                             const cfd::Vec3& gravity, const std::array<bool, 3>& dem_periodic) {
  std::vector<char> is_wall(mesh.patchNames().size(), 0);
  for (const cfd::BoundarySettings& bc : boundaries) {
    const int id = mesh.patchId(bc.patch);
    if (id >= 0)
      is_wall[id] = bc.type == cfd::BoundaryType::NoSlipWall || bc.type == cfd::BoundaryType::FreeSlipWall;
  }
  const double g = gravity.norm();
  double area = 0.0;
  for (int b = 0; b < mesh.nBoundaryFaces(); ++b) {
    if (!is_wall[mesh.boundaryPatch(b)]) continue;
    const cfd::Vec3 n = mesh.boundaryArea(b) / mesh.boundaryMagArea(b);
    if (g > 0.0 && std::abs(n.dot(gravity)) >= 0.5 * g) continue;  // a floor or a roof
    bool through_periodic_face = false;
    for (int d = 0; d < 3; ++d)
      through_periodic_face = through_periodic_face || (dem_periodic[d] && std::abs(n[d]) > 0.99);
    if (!through_periodic_face) area += mesh.boundaryMagArea(b);
  }
  double volume = 0.0;
  for (int c = 0; c < mesh.nOwnedCells(); ++c) volume += mesh.cellVolume(c);
  const double total_volume = mesh.sum(volume);
  return total_volume > 0.0 ? mesh.sum(area) / total_volume : 0.0;
}

double narrowestExtentBetweenWalls(const std::array<double, 3>& box_lengths, const std::array<bool, 3>& dem_periodic) {
  double narrowest = std::numeric_limits<double>::infinity();
  for (int d = 0; d < 3; ++d)
    if (!dem_periodic[d]) narrowest = std::min(narrowest, box_lengths[d]);
  return narrowest;
}

}  // namespace parcelflow::coupling
