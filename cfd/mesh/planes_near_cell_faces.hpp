#pragma once
// Axis-aligned planes of the geometry (a box's faces, a cylinder's or cone's ends) that lie a hair off a
// background cell face, closer than mesh.small_cell_fraction of the cell but not on it. On cut cells such a
// plane leaves a film of fluid across the faces of the cells beyond it; where those cells hold other fluid as
// well the film is not merged away, and the gas there goes wrong: the full FCC case's lid, 4e-8 m above a face
// (lengths 7.4935897 for 167 cells), left films under the exit tube's foot whose cells carried gas speeds
// growing to 60,000 m/s, and the run diverged within 0.13 s (cfd/README.md, "Known defect: a wall a hair off a
// cell face"). One message per such plane, naming it, the face and the distance.
#include <string>
#include <vector>

#include "cfd/geometry/geometry.hpp"
#include "cfd/mesh/mesh_settings.hpp"

namespace parcelflow::cfd {

std::vector<std::string> planesNearCellFaces(const MeshSettings& mesh, const Geometry& geometry);

}  // namespace parcelflow::cfd
