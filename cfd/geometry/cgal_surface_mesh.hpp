#pragma once
// CGAL types of the cut-cell geometry, for its .cpp files only (never include this from a public header:
// CGAL is heavy to compile and wants -frounding-math, which the solver's code does not need).
// Kernel: exact predicates, double coordinates. The corefinement (clip, booleans) computes its
// intersection points exactly and rounds them once, so a point on a cell's face plane keeps that plane's
// coordinate exactly: the open-face areas rely on it (cut_cell_geometry.cpp).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <string>

#include "cfd/geometry/triangle_surface.hpp"

namespace parcelflow::cfd::cgal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

inline Point toPoint(const Vec3& v) { return Point(v[0], v[1], v[2]); }
inline Vec3 toVec3(const Point& p) { return Vec3(p.x(), p.y(), p.z()); }

// What is wrong with a triangle soup as the boundary of a solid; "" when it is a closed, consistently
// oriented, manifold, self-intersection-free surface enclosing a positive volume. On success `mesh`
// holds it.
std::string closedSurfaceProblem(const std::vector<Point>& points,
                                 const std::vector<std::array<int, 3>>& triangles, Mesh& mesh);

Mesh toMesh(const TriangleSurface& surface);  // the surface must be a valid mesh (PARCELFLOW_ASSERT)
TriangleSurface toSurface(const Mesh& mesh);

// A closed, outward-oriented triangulated axis-aligned box.
Mesh boxMesh(const Vec3& lo, const Vec3& hi);

}  // namespace parcelflow::cfd::cgal
