#pragma once
// Measures one cut cell: the closed polyhedron `fluid ∩ cell box` (from CGAL's clip) split into its
// volume and centroid, the open area (and its centroid) on each of the box's 6 faces and the wall (every
// other face). Internal to
// cut_cell_geometry.cpp (CGAL types).
#include <array>
#include <map>
#include <utility>
#include <vector>

#include "cfd/geometry/cgal_surface_mesh.hpp"
#include "cfd/geometry/cut_cell_geometry.hpp"

namespace parcelflow::cfd {

// The fluid-surface triangles that lie exactly in a grid plane, by (axis, plane index): a clipped
// polyhedron's face in a cell's face plane is wall, not open face, when it lies on one of them.
class CoplanarSurfaceIndex {
 public:
  CoplanarSurfaceIndex(const TriangleSurface& surface, const CartesianBackground& background);
  bool onSurface(int axis, int plane, const Vec3& point) const;

 private:
  std::map<std::pair<int, int>, std::vector<std::array<Vec3, 3>>> triangles_;
};

struct CutCellMeasure {
  double volume = 0;
  Vec3 centroid = Vec3::Zero();  // of the fluid volume (first moment / volume)
  std::array<double, 6> openArea{};  // per CellFace
  std::array<Vec3, 6> openCentroid{};  // per CellFace, area-weighted; zero for a closed face
  CutCellWall wall;
  double closureError = 0;  // |sum of outward area vectors|, should be round-off
};

// `lo`/`hi` are the cell's box, `ijk` its background index (for the grid-plane indices),
// `onBackgroundBoundary[f]` whether face f lies on the background box's side (a surface lying there is
// the boundary patch's business and counts as open face, not wall).
CutCellMeasure measureCutCell(const cgal::Mesh& clipped, const Vec3& lo, const Vec3& hi,
                              const std::array<int, 3>& ijk, const std::array<bool, 6>& onBackgroundBoundary,
                              const CoplanarSurfaceIndex& coplanar);

}  // namespace parcelflow::cfd
