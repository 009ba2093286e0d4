#pragma once
// A closed triangulated surface bounding the fluid (outward normals: counter-clockwise seen from the
// solid side), as plain arrays. It is the hand-over between the surface sources (an STL file, the
// `geometry:` primitives) and the cut-cell geometry, and keeps CGAL out of every public header: only the
// .cpp files that compute with the surface include CGAL (cgal_surface_mesh.hpp).
#include <array>
#include <vector>

#include "cfd/base/types.hpp"

namespace parcelflow::cfd {

struct TriangleSurface {
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;  // indices into points, counter-clockwise seen from outside

  // Enclosed volume (divergence theorem; positive for outward normals) and total area.
  double volume() const;
  double area() const;
};

}  // namespace parcelflow::cfd
