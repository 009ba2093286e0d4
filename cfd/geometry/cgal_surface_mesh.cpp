#include "cfd/geometry/cgal_surface_mesh.hpp"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include "cfd/base/internal_error.hpp"

namespace parcelflow::cfd::cgal {

namespace PMP = CGAL::Polygon_mesh_processing;

std::string closedSurfaceProblem(const std::vector<Point>& points,
                                 const std::vector<std::array<int, 3>>& triangles, Mesh& mesh) {
  if (triangles.empty()) return "it has no triangles";
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& v = triangles[t];
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
      return "triangle " + std::to_string(t) + " has two identical corners (degenerate)";
  }
  // A soup is a mesh when every edge has at most two triangles that traverse it in opposite directions
  // and every vertex has one fan: this is the consistent-orientation and manifold test.
  if (!PMP::is_polygon_soup_a_polygon_mesh(triangles))
    return "it is not a consistently oriented manifold surface (an edge is shared by more than two "
           "triangles, or two triangles sharing an edge traverse it in the same direction)";
  mesh.clear();
  PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  std::size_t borderEdges = 0;
  for (auto h : mesh.halfedges())
    if (mesh.is_border(h)) ++borderEdges;
  if (borderEdges > 0)
    return "it is not closed (" + std::to_string(borderEdges) + " edges belong to one triangle only)";
  if (PMP::does_self_intersect(mesh)) return "it intersects itself";
  const double volume = PMP::volume(mesh);
  if (!(volume > 0))
    return "its enclosed volume is " + std::to_string(volume) +
           " (inverted: the triangles' normals must point out of the fluid)";
  return "";
}

Mesh toMesh(const TriangleSurface& surface) {
  std::vector<Point> points;
  points.reserve(surface.points.size());
  for (const auto& p : surface.points) points.push_back(toPoint(p));
  Mesh mesh;
  const std::string problem = closedSurfaceProblem(points, surface.triangles, mesh);
  PARCELFLOW_ASSERT(problem.empty(), "a surface built by parcelflow is not a closed solid: " + problem);
  return mesh;
}

TriangleSurface toSurface(const Mesh& mesh) {
  TriangleSurface s;
  std::vector<int> indexOf(mesh.number_of_vertices() + mesh.number_of_removed_vertices(), -1);
  for (auto v : mesh.vertices()) {
    indexOf[v.idx()] = static_cast<int>(s.points.size());
    s.points.push_back(toVec3(mesh.point(v)));
  }
  for (auto f : mesh.faces()) {
    std::array<int, 3> t{};
    int n = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      PARCELFLOW_ASSERT(n < 3, "surface mesh face is not a triangle");
      t[n++] = indexOf[v.idx()];
    }
    PARCELFLOW_ASSERT(n == 3, "surface mesh face is not a triangle");
    s.triangles.push_back(t);
  }
  return s;
}

Mesh boxMesh(const Vec3& lo, const Vec3& hi) {
  // Corner b has x from bit 0, y from bit 1, z from bit 2; two triangles per side, counter-clockwise
  // seen from outside.
  std::vector<Point> corners;
  for (int b = 0; b < 8; ++b)
    corners.emplace_back((b & 1) ? hi[0] : lo[0], (b & 2) ? hi[1] : lo[1], (b & 4) ? hi[2] : lo[2]);
  static const std::vector<std::array<int, 3>> sides = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6},
                                                        {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3},
                                                        {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(corners, sides, mesh);
  return mesh;
}

}  // namespace parcelflow::cfd::cgal
