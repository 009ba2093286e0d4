#include "primitive.hpp"

#include <cmath>

#include "config_error.hpp"
#include "yaml_section.hpp"

namespace parcelflow::cfd {

Primitive Primitive::box(const Vec3& lo, const Vec3& hi) {
  Primitive p;
  p.kind_ = Kind::Box;
  p.lo_ = lo;
  p.hi_ = hi;
  return p;
}

Primitive Primitive::cylinder(double cx, double cy, double radius, double zmin, double zmax) {
  Primitive p;
  p.kind_ = Kind::Cylinder;
  p.cx_ = cx;
  p.cy_ = cy;
  p.radius_ = radius;
  p.lo_ = Vec3(cx - radius, cy - radius, zmin);
  p.hi_ = Vec3(cx + radius, cy + radius, zmax);
  return p;
}

Primitive Primitive::fromYaml(const YamlSection& section) {
  const std::string kind = section.singleKey({"box", "cylinder"});
  const YamlSection s = section.map(kind);
  if (kind == "box") {
    s.allowOnly({"min", "max"});
    const Vec3 lo = s.vec3("min", std::nullopt, Range::any());
    const Vec3 hi = s.vec3("max", std::nullopt, Range::any());
    for (int c = 0; c < 3; ++c)
      if (!(hi[c] > lo[c])) s.fail("max", "must be larger than min in every component");
    return box(lo, hi);
  }
  s.allowOnly({"center", "radius", "zmin", "zmax"});
  const double radius = s.number("radius", std::nullopt, Range::positive());
  const double zmin = s.number("zmin", std::nullopt, Range::any());
  const double zmax = s.number("zmax", std::nullopt, Range::any());
  if (!(zmax > zmin)) s.fail("zmax", "must be larger than zmin");
  const auto xy = s.numbers("center", 2, Range::any());
  return cylinder(xy[0], xy[1], radius, zmin, zmax);
}

bool Primitive::contains(const Vec3& x) const {
  if (kind_ == Kind::Box)
    return x[0] >= lo_[0] && x[0] <= hi_[0] && x[1] >= lo_[1] && x[1] <= hi_[1] && x[2] >= lo_[2] &&
           x[2] <= hi_[2];
  const double dx = x[0] - cx_, dy = x[1] - cy_;
  return x[2] >= lo_[2] && x[2] <= hi_[2] && dx * dx + dy * dy <= radius_ * radius_;
}

double Primitive::volume() const {
  if (kind_ == Kind::Box) return (hi_ - lo_).prod();
  return M_PI * radius_ * radius_ * (hi_[2] - lo_[2]);
}

}  // namespace parcelflow::cfd
