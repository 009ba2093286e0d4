#include "cfd/geometry/surface_from_geometry.hpp"

#include <CGAL/Polygon_mesh_processing/corefinement.h>

#include <cmath>
#include <vector>

#include "cfd/geometry/cgal_surface_mesh.hpp"
#include "cfd/base/config_error.hpp"
#include "cfd/base/internal_error.hpp"

namespace parcelflow::cfd {

namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

// Triangulates a polygon cap by a zigzag strip (corners 0, 1, n-1, 2, n-2, ...), oriented so that its
// normal has the sign `upward` along z. No centre point: caps of concentric shapes meeting in one
// plane (the FCC column's top and its exit tube's bottom) would otherwise share a centre with every
// triangle of both fans, and CGAL's coplanar intersection code took 55 s on that union.
void addCap(TriangleSurface& s, int first, int n, bool upward) {
  std::vector<int> order;
  for (int lo = 0, hi = n - 1; lo <= hi; ++lo, --hi) {
    order.push_back(first + lo);
    if (hi != lo) order.push_back(first + hi);
  }
  for (std::size_t m = 0; m + 2 < order.size(); ++m) {
    std::array<int, 3> t = {order[m], order[m + 1], order[m + 2]};
    const Vec3 &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
    const double z = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if ((z > 0) != upward) std::swap(t[1], t[2]);
    s.triangles.push_back(t);
  }
}

// A frustum along z over regular polygons (a cylinder when both radii are equal). A zero radius end is
// one apex point instead of a polygon.
TriangleSurface roundSurface(const Primitive& p, int segments, double phase) {
  const double z[2] = {p.lo()[2], p.hi()[2]};
  const double r[2] = {p.radiusAtZmin(), p.radiusAtZmax()};
  TriangleSurface s;
  int ring[2] = {-1, -1};  // first polygon point of each end, -1 for an apex
  int apex[2] = {-1, -1};
  for (int end = 0; end < 2; ++end) {
    if (r[end] == 0) {
      apex[end] = static_cast<int>(s.points.size());
      s.points.emplace_back(p.axisX(), p.axisY(), z[end]);
      continue;
    }
    ring[end] = static_cast<int>(s.points.size());
    for (int k = 0; k < segments; ++k) {
      const double angle = 2 * M_PI * (k + phase) / segments;
      s.points.emplace_back(p.axisX() + r[end] * std::cos(angle), p.axisY() + r[end] * std::sin(angle), z[end]);
    }
    addCap(s, ring[end], segments, end == 1);  // bottom seen from below, top from above: counter-clockwise
  }
  auto at = [&](int end, int k) { return ring[end] < 0 ? apex[end] : ring[end] + (k % segments); };
  for (int k = 0; k < segments; ++k) {
    // Side quad (k, k+1) from bottom to top, split into two triangles (one when an end is an apex).
    if (ring[0] >= 0) s.triangles.push_back({at(0, k), at(0, k + 1), at(1, k + 1)});
    if (ring[1] >= 0) s.triangles.push_back({at(0, k), at(1, k + 1), at(1, k)});
  }
  return s;
}

TriangleSurface boxSurface(const Vec3& lo, const Vec3& hi) { return cgal::toSurface(cgal::boxMesh(lo, hi)); }

}  // namespace

TriangleSurface surfaceOfPrimitive(const Primitive& primitive, int segments, double phase) {
  if (primitive.kind() == Primitive::Kind::Box) return boxSurface(primitive.lo(), primitive.hi());
  if (primitive.kind() == Primitive::Kind::Surface) return primitive.triangles();
  if (segments < 3)
    throw ConfigError("circle segments", std::to_string(segments), "an integer of at least 3");
  return roundSurface(primitive, segments, phase);
}

TriangleSurface surfaceOfGeometry(const Geometry& geometry, const CartesianBackground& background,
                                  int segments) {
  if (geometry.items().empty()) {
    const Vec3 lo = background.origin();
    Vec3 hi;
    for (int d = 0; d < 3; ++d) hi[d] = lo[d] + background.n()[d] * background.spacing()[d];
    return boxSurface(lo, hi);
  }
  cgal::Mesh fluid;  // empty until the first union
  int index = 0;
  for (const auto& item : geometry.items()) {
    const double phase = std::fmod(0.6180339887498949 * index, 1.0);
    cgal::Mesh shape = cgal::toMesh(surfaceOfPrimitive(item.primitive, segments, phase));
    const std::string where = "geometry[" + std::to_string(index++) + "]";
    if (item.op == Geometry::Op::Union) {
      if (fluid.is_empty()) {
        fluid = std::move(shape);
        continue;
      }
      if (!PMP::corefine_and_compute_union(fluid, shape, fluid))
        throw ConfigError(where, "op: union",
                          "shapes whose union is a manifold solid (this one touches the fluid so far only "
                          "along an edge or at a point)");
    } else if (!fluid.is_empty()) {
      if (!PMP::corefine_and_compute_difference(fluid, shape, fluid))
        throw ConfigError(where, "op: cut",
                          "cut-outs that leave a manifold solid (this one leaves parts touching only along "
                          "an edge or at a point)");
    }
  }
  if (fluid.is_empty() || fluid.number_of_faces() == 0)
    throw ConfigError("geometry", "(" + std::to_string(geometry.items().size()) + " shapes)",
                      "shapes that leave some fluid (the cut-outs remove all of it)");
  fluid.collect_garbage();
  return cgal::toSurface(fluid);
}

}  // namespace parcelflow::cfd
