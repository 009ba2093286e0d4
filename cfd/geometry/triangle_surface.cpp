#include "cfd/geometry/triangle_surface.hpp"

#include <Eigen/Geometry>  // cross products

namespace parcelflow::cfd {

double TriangleSurface::volume() const {
  // Sum of the signed tetrahedra (origin, triangle): exact for a closed surface whatever the origin;
  // taking the first point as origin keeps the terms small for surfaces far from (0, 0, 0).
  if (points.empty()) return 0.0;
  const Vec3& o = points.front();
  double sixTimesVolume = 0.0;
  for (const auto& t : triangles)
    sixTimesVolume += (points[t[0]] - o).dot((points[t[1]] - o).cross(points[t[2]] - o));
  return sixTimesVolume / 6.0;
}

double TriangleSurface::area() const {
  double twiceArea = 0.0;
  for (const auto& t : triangles)
    twiceArea += (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]).norm();
  return 0.5 * twiceArea;
}

}  // namespace parcelflow::cfd
