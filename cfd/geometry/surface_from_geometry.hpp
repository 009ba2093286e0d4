#pragma once
// Turns the `geometry:` list (unions and cut-outs of boxes, cylinders and cones, in list order) into one
// closed triangulated fluid surface, so that primitives and STL files reach the cut-cell geometry
// through the same code path. Round primitives become prisms/frusta over a regular polygon of
// `segments` corners on the circle (inscribed: the polygon's area is (segments/2) r^2 sin(2 pi/segments),
// 4.0e-4 below pi r^2 at 128 segments; caps are zigzag strips, no centre point); the booleans are
// CGAL's corefinement (exact predicates). An
// empty list is the whole background box, as in Geometry::isFluid. The n-th shape's polygon is turned by
// frac(0.618 n) of a segment: concentric shapes with corners on the same rays are near-degenerate
// contacts whose rounded intersection points made the result self-intersecting (measured: a cone with a
// cylinder cut out along its axis, with centre-fan caps); turned polygons meet in proper crossings.
#include "cfd/geometry/cartesian_background.hpp"
#include "cfd/geometry/geometry.hpp"
#include "cfd/geometry/triangle_surface.hpp"

namespace parcelflow::cfd {

// Corners of a tessellated circle unless a case says otherwise: the column of
// cases/psri_fcc_bubbling_bed then keeps its volume to 4.0e-4 (cfd/README.md, "Cut-cell geometry").
constexpr int defaultCircleSegments = 128;

// `phase`: the polygon's first corner sits at angle phase * 2 pi / segments.
TriangleSurface surfaceOfPrimitive(const Primitive& primitive, int segments, double phase = 0);
TriangleSurface surfaceOfGeometry(const Geometry& geometry, const CartesianBackground& background,
                                  int segments = defaultCircleSegments);

}  // namespace parcelflow::cfd
