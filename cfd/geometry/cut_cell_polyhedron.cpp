#include "cfd/geometry/cut_cell_polyhedron.hpp"

#include <Eigen/Geometry>  // cross products
#include <algorithm>
#include <cmath>
#include <vector>

namespace parcelflow::cfd {

namespace {

// Twice the signed area of the 2-D triangle (a, b, c).
double orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

}  // namespace

CoplanarSurfaceIndex::CoplanarSurfaceIndex(const TriangleSurface& surface,
                                           const CartesianBackground& background) {
  for (const auto& t : surface.triangles) {
    const std::array<Vec3, 3> p = {surface.points[t[0]], surface.points[t[1]], surface.points[t[2]]};
    for (int d = 0; d < 3; ++d) {
      if (p[0][d] != p[1][d] || p[0][d] != p[2][d]) continue;
      const double h = background.spacing()[d], o = background.origin()[d];
      const long plane = std::lround((p[0][d] - o) / h);
      // Only exact grid planes matter: the surface was snapped onto them (cut_cell_geometry.cpp).
      if (o + plane * h == p[0][d]) triangles_[{d, static_cast<int>(plane)}].push_back(p);
    }
  }
}

bool CoplanarSurfaceIndex::onSurface(int axis, int plane, const Vec3& point) const {
  const auto it = triangles_.find({axis, plane});
  if (it == triangles_.end()) return false;
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  for (const auto& t : it->second) {
    const double whole = orient2d(t[0][a], t[0][b], t[1][a], t[1][b], t[2][a], t[2][b]);
    const double tolerance = 1e-12 * std::abs(whole);
    const double sign = whole > 0 ? 1.0 : -1.0;
    bool inside = true;
    for (int e = 0; e < 3 && inside; ++e) {
      const auto& u = t[e];
      const auto& v = t[(e + 1) % 3];
      inside = sign * orient2d(u[a], u[b], v[a], v[b], point[a], point[b]) >= -tolerance;
    }
    if (inside) return true;
  }
  return false;
}

namespace {

bool lexicographicallyLess(const Vec3& a, const Vec3& b) {
  return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
}

// The clipped piece's triangles in an order and with a first corner that depend on their coordinates only:
// CGAL's corefinement orders its work by the addresses of its boxes (ID_FROM_BOX_ADDRESS), so two clips of
// one cell give the same triangles in another order, and sums over them would differ in the last bits
// between two builds of one mesh (and a restarted run would not continue bit for bit).
std::vector<std::array<Vec3, 3>> canonicalTriangles(const cgal::Mesh& clipped) {
  std::vector<std::array<Vec3, 3>> triangles;
  triangles.reserve(clipped.number_of_faces());
  for (auto f : clipped.faces()) {
    std::array<Vec3, 3> p;
    int n = 0;
    for (auto v : CGAL::vertices_around_face(clipped.halfedge(f), clipped)) p[n++] = cgal::toVec3(clipped.point(v));
    // the smallest corner first, the orientation kept
    const int first = lexicographicallyLess(p[1], p[0]) ? (lexicographicallyLess(p[2], p[1]) ? 2 : 1)
                                                         : (lexicographicallyLess(p[2], p[0]) ? 2 : 0);
    std::rotate(p.begin(), p.begin() + first, p.end());
    triangles.push_back(p);
  }
  std::sort(triangles.begin(), triangles.end(), [](const auto& a, const auto& b) {
    for (int v = 0; v < 3; ++v) {
      if (lexicographicallyLess(a[v], b[v])) return true;
      if (lexicographicallyLess(b[v], a[v])) return false;
    }
    return false;
  });
  return triangles;
}

}  // namespace

CutCellMeasure measureCutCell(const cgal::Mesh& clipped, const Vec3& lo, const Vec3& hi,
                              const std::array<int, 3>& ijk, const std::array<bool, 6>& onBackgroundBoundary,
                              const CoplanarSurfaceIndex& coplanar) {
  CutCellMeasure m;
  Vec3 closure = Vec3::Zero();
  double sixTimesVolume = 0;
  Vec3 twentyFourTimesMoment = Vec3::Zero();  // first moment of the volume about lo, times 24
  Vec3 wallMoment = Vec3::Zero();
  std::array<Vec3, 6> openMoment;
  openMoment.fill(Vec3::Zero());
  for (const std::array<Vec3, 3>& p : canonicalTriangles(clipped)) {
    // Volume relative to the cell's lower corner: small terms, no cancellation of large coordinates.
    // Each face spans a tetrahedron with lo: volume det/6, centroid lo + (sum of the corners - lo)/4.
    const double det = (p[0] - lo).dot((p[1] - lo).cross(p[2] - lo));
    sixTimesVolume += det;
    twentyFourTimesMoment += det * ((p[0] - lo) + (p[1] - lo) + (p[2] - lo));
    const Vec3 areaVector = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]);
    const double area = areaVector.norm();
    const Vec3 centroid = (p[0] + p[1] + p[2]) / 3.0;
    closure += areaVector;

    // A face in one of the box's planes: every corner within round-off (1e-12 of the cell) of that
    // plane and the normal along the plane's outward axis. The clip rounds its intersection points once,
    // so corners land on a plane to about 1e-16 of the cell.
    int boxFace = -1;
    for (int d = 0; d < 3 && boxFace < 0; ++d)
      for (int side = 0; side < 2 && boxFace < 0; ++side) {
        const double c = side ? hi[d] : lo[d], tolerance = 1e-12 * (hi[d] - lo[d]);
        bool inPlane = (side ? areaVector[d] : -areaVector[d]) > (1 - 1e-12) * area;
        for (int v = 0; v < 3 && inPlane; ++v) inPlane = std::abs(p[v][d] - c) <= tolerance;
        if (inPlane) boxFace = 2 * d + side;
      }
    bool isWall = boxFace < 0;
    if (!isWall && !onBackgroundBoundary[boxFace]) {
      const int d = boxFace / 2;
      isWall = coplanar.onSurface(d, ijk[d] + boxFace % 2, centroid);
    }
    if (isWall) {
      m.wall.area += area;
      m.wall.areaVector += areaVector;
      wallMoment += area * centroid;
    } else {
      m.openArea[boxFace] += area;
      openMoment[boxFace] += area * centroid;
    }
  }
  m.volume = sixTimesVolume / 6.0;
  // A cell whose box only touches the surface has no volume: its centroid is the box centre.
  m.centroid = sixTimesVolume > 0 ? Vec3(lo + twentyFourTimesMoment / (4.0 * sixTimesVolume)) : Vec3(0.5 * (lo + hi));
  if (m.wall.area > 0) m.wall.centroid = wallMoment / m.wall.area;
  for (int f = 0; f < 6; ++f)
    if (m.openArea[f] > 0) m.openCentroid[f] = openMoment[f] / m.openArea[f];
  // Closure from the classified parts: open faces have the box's outward axis normals.
  Vec3 classified = m.wall.areaVector;
  for (int f = 0; f < 6; ++f) classified[f / 2] += (f % 2 ? 1.0 : -1.0) * m.openArea[f];
  m.closureError = std::max(closure.norm(), classified.norm());
  return m;
}

}  // namespace parcelflow::cfd
