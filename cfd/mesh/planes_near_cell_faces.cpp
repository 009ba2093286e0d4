#include "cfd/mesh/planes_near_cell_faces.hpp"

#include "cfd/geometry/cartesian_background.hpp"
#include "cfd/base/number_text.hpp"

namespace parcelflow::cfd {

std::vector<std::string> planesNearCellFaces(const MeshSettings& mesh, const Geometry& geometry) {
  std::vector<std::string> found;
  const CartesianBackground background(mesh.origin, mesh.lengths, mesh.cells);  // the mesh's own cell size
  const char* axisName = "xyz";
  for (std::size_t i = 0; i < geometry.items().size(); ++i) {
    const Primitive& p = geometry.items()[i].primitive;
    if (p.kind() == Primitive::Kind::Surface) continue;  // no axis-aligned planes of its own
    for (int d = 0; d < 3; ++d) {
      if (p.kind() != Primitive::Kind::Box && d != 2) continue;  // cylinders and cones: their ends only
      const double h = background.spacing()[d];
      for (const double plane : {p.lo()[d], p.hi()[d]}) {
        // on the nearest face as the cut-cell geometry sees it (it snaps planes within kOnGridPlane), or off it
        const auto nearest = background.nearestPlane(d, plane);
        if (nearest.offSpacings >= kOnGridPlane && nearest.offSpacings < mesh.smallCellFraction)
          found.push_back("geometry item " + std::to_string(i + 1) + ": its plane " + axisName[d] + " = " +
                          shortNumber(plane) + " lies " + formatNumbers("%.3g", nearest.offSpacings * h) +
                          " m off the cell face at " + exactNumber(background.planeCoordinate(d, nearest.plane)) +
                          " (less than mesh.small_cell_fraction " +
                          shortNumber(mesh.smallCellFraction) + " of the cell, " + shortNumber(h) + " m)");
      }
    }
  }
  return found;
}

}  // namespace parcelflow::cfd
