#pragma once
// A geometric primitive used to select fluid cells and to define regions (inlet regions, partition
// weights): an axis-aligned box, a cylinder along z, a cone frustum along z (a radius at each end) or a
// closed surface from an STL file. A cell belongs to it when its centre is inside (staircase walls); the
// cut-cell geometry turns the same primitives into a triangulated surface instead
// (surface_from_geometry.hpp).
#include <memory>
#include <string>

#include "cfd/base/types.hpp"

namespace parcelflow::cfd {

class YamlSection;
class SolidSurface;
struct TriangleSurface;

class Primitive {
 public:
  enum class Kind { Box, Cylinder, Cone, Surface };

  static Primitive box(const Vec3& lo, const Vec3& hi);
  static Primitive cylinder(double cx, double cy, double radius, double zmin, double zmax);
  // Frustum along z: radius `radiusZmin` at zmin, `radiusZmax` at zmax (one of them may be 0: a cone).
  static Primitive cone(double cx, double cy, double radiusZmin, double radiusZmax, double zmin, double zmax);
  static Primitive surface(std::shared_ptr<const SolidSurface> solid);
  // Reads `{box: {min: [..], max: [..]}}`, `{cylinder: {center: [x, y], radius, zmin, zmax}}`,
  // `{cone: {center: [x, y], radius_zmin, radius_zmax, zmin, zmax}}` or `{stl: {file: path}}` (a path
  // relative to `caseFolder` unless absolute) from the section holding that single key.
  static Primitive fromYaml(const YamlSection& section, const std::string& caseFolder);

  bool contains(const Vec3& x) const;
  Kind kind() const { return kind_; }
  // Box corners, or the bounding box of a cylinder, cone or surface.
  const Vec3& lo() const { return lo_; }
  const Vec3& hi() const { return hi_; }
  // Axis position (cylinder, cone) and the radius at zmin and at zmax (equal for a cylinder).
  double axisX() const { return cx_; }
  double axisY() const { return cy_; }
  double radiusAtZmin() const { return radius_; }
  double radiusAtZmax() const { return kind_ == Kind::Cone ? radiusTop_ : radius_; }
  // The closed surface of a Surface primitive (PARCELFLOW_ASSERT on other kinds).
  const TriangleSurface& triangles() const;
  // Approximate volume, for reporting only.
  double volume() const;

 private:
  Kind kind_ = Kind::Box;
  Vec3 lo_ = Vec3::Zero(), hi_ = Vec3::Zero();  // box corners, or cylinder bounding box
  double cx_ = 0, cy_ = 0, radius_ = 0;  // radius_: of the cylinder, or of the cone at zmin
  double radiusTop_ = 0;                   // cone: radius at zmax
  std::shared_ptr<const SolidSurface> solid_;  // surface: shared by the copies of the settings
};

}  // namespace parcelflow::cfd
