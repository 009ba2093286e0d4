#pragma once
// The test column of the mesh tests: R 0.1 m up to 0.4 m, a narrower exit tube (R 0.04 m) up to 0.5 m, and a
// baffle cut out with its own wall patch.
#include "cfd/geometry/geometry.hpp"

namespace parcelflow::cfd::test {

inline Geometry columnGeometry() {
  return Geometry({{Geometry::Op::Union, Primitive::cylinder(0, 0, 0.1, 0, 0.4), ""},
                   {Geometry::Op::Union, Primitive::cylinder(0, 0, 0.04, 0.4, 0.5), ""},
                   {Geometry::Op::Cut, Primitive::box(Vec3(-0.03, -0.03, 0.2), Vec3(0.03, 0.03, 0.24)),
                    "baffle"}});
}

}  // namespace parcelflow::cfd::test
