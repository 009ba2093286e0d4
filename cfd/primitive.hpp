#pragma once
// A geometric primitive used to select fluid cells and to define regions (inlet regions, partition
// weights): an axis-aligned box or a cylinder along z. A cell belongs to it when its centre is inside
// (staircase walls); cut cells would replace this test, not the data structure.
#include <string>

#include "types.hpp"

namespace parcelflow::cfd {

class YamlSection;

class Primitive {
 public:
  enum class Kind { Box, Cylinder };

  static Primitive box(const Vec3& lo, const Vec3& hi);
  static Primitive cylinder(double cx, double cy, double radius, double zmin, double zmax);
  // Reads `{box: {min: [..], max: [..]}}` or `{cylinder: {center: [x, y], radius, zmin, zmax}}` from
  // the section holding that single key.
  static Primitive fromYaml(const YamlSection& section);

  bool contains(const Vec3& x) const;
  Kind kind() const { return kind_; }
  // Approximate volume, for reporting only.
  double volume() const;

 private:
  Kind kind_ = Kind::Box;
  Vec3 lo_ = Vec3::Zero(), hi_ = Vec3::Zero();  // box corners, or cylinder bounding box
  double cx_ = 0, cy_ = 0, radius_ = 0;
};

}  // namespace parcelflow::cfd
