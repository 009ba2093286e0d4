#include "surface_from_geometry.hpp"

#include <CGAL/Polygon_mesh_processing/corefinement.h>

#include <cmath>

#include "cgal_surface_mesh.hpp"
#include "config_error.hpp"
#include "internal_error.hpp"

namespace parcelflow::cfd {

namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

// A frustum along z over regular polygons (a cylinder when both radii are equal). A zero radius end is
// one apex point instead of a polygon. Caps are fans around their centre point (no sliver triangles).
TriangleSurface roundSurface(const Primitive& p, int segments, double phase) {
  const double z[2] = {p.lo()[2], p.hi()[2]};
  const double r[2] = {p.radiusAtZmin(), p.radiusAtZmax()};
  TriangleSurface s;
  int ring[2] = {-1, -1};  // first polygon point of each end, -1 for an apex
  int centre[2];
  for (int end = 0; end < 2; ++end) {
    centre[end] = static_cast<int>(s.points.size());
    s.points.emplace_back(p.axisX(), p.axisY(), z[end]);
    if (r[end] == 0) continue;
    ring[end] = static_cast<int>(s.points.size());
    for (int k = 0; k < segments; ++k) {
      const double angle = 2 * M_PI * (k + phase) / segments;
      s.points.emplace_back(p.axisX() + r[end] * std::cos(angle), p.axisY() + r[end] * std::sin(angle), z[end]);
    }
  }
  auto at = [&](int end, int k) { return ring[end] < 0 ? centre[end] : ring[end] + (k % segments); };
  for (int k = 0; k < segments; ++k) {
    // Bottom cap seen from below and top cap seen from above are counter-clockwise.
    if (ring[0] >= 0) s.triangles.push_back({centre[0], at(0, k + 1), at(0, k)});
    if (ring[1] >= 0) s.triangles.push_back({centre[1], at(1, k), at(1, k + 1)});
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
