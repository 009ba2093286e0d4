#include "cfd/geometry/primitive.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "cfd/base/config_error.hpp"
#include "cfd/base/internal_error.hpp"
#include "cfd/geometry/solid_surface.hpp"
#include "cfd/io/yaml_section.hpp"

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

Primitive Primitive::cone(double cx, double cy, double radiusZmin, double radiusZmax, double zmin,
                          double zmax) {
  Primitive p = cylinder(cx, cy, std::max(radiusZmin, radiusZmax), zmin, zmax);
  p.kind_ = Kind::Cone;
  p.radius_ = radiusZmin;
  p.radiusTop_ = radiusZmax;
  return p;
}

Primitive Primitive::surface(std::shared_ptr<const SolidSurface> solid) {
  Primitive p;
  p.kind_ = Kind::Surface;
  p.lo_ = solid->lo();
  p.hi_ = solid->hi();
  p.solid_ = std::move(solid);
  return p;
}

Primitive Primitive::fromYaml(const YamlSection& section, const std::string& caseFolder) {
  const std::string kind = section.singleKey({"box", "cylinder", "cone", "stl"});
  const YamlSection s = section.map(kind);
  if (kind == "stl") {
    s.allowOnly({"file"});
    const std::filesystem::path file = s.text("file", std::nullopt);
    const std::string path = file.is_absolute() ? file.string() : (std::filesystem::path(caseFolder) / file).string();
    return surface(SolidSurface::fromStl(path, s.keyPath("file")));
  }
  if (kind == "box") {
    s.allowOnly({"min", "max"});
    const Vec3 lo = s.vec3("min", std::nullopt, Range::any());
    const Vec3 hi = s.vec3("max", std::nullopt, Range::any());
    for (int c = 0; c < 3; ++c)
      if (!(hi[c] > lo[c])) s.fail("max", "must be larger than min in every component");
    return box(lo, hi);
  }
  if (kind == "cone") {
    s.allowOnly({"center", "radius_zmin", "radius_zmax", "zmin", "zmax"});
    const double r0 = s.number("radius_zmin", std::nullopt, Range::nonNegative());
    const double r1 = s.number("radius_zmax", std::nullopt, Range::nonNegative());
    if (!(r0 > 0 || r1 > 0)) s.fail("radius_zmax", "must be positive when radius_zmin is 0");
    const double zmin = s.number("zmin", std::nullopt, Range::any());
    const double zmax = s.number("zmax", std::nullopt, Range::any());
    if (!(zmax > zmin)) s.fail("zmax", "must be larger than zmin");
    const auto xy = s.numbers("center", 2, Range::any());
    return cone(xy[0], xy[1], r0, r1, zmin, zmax);
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
  if (kind_ == Kind::Surface) return solid_->contains(x);
  if (kind_ == Kind::Box)
    return x[0] >= lo_[0] && x[0] <= hi_[0] && x[1] >= lo_[1] && x[1] <= hi_[1] && x[2] >= lo_[2] &&
           x[2] <= hi_[2];
  if (x[2] < lo_[2] || x[2] > hi_[2]) return false;
  const double dx = x[0] - cx_, dy = x[1] - cy_;
  const double r = kind_ == Kind::Cone ? radius_ + (radiusTop_ - radius_) * (x[2] - lo_[2]) / (hi_[2] - lo_[2])
                                       : radius_;
  return dx * dx + dy * dy <= r * r;
}

const TriangleSurface& Primitive::triangles() const {
  PARCELFLOW_ASSERT(kind_ == Kind::Surface, "triangles() of a primitive that is not a surface");
  return solid_->triangles();
}

double Primitive::volume() const {
  if (kind_ == Kind::Surface) return solid_->triangles().volume();
  if (kind_ == Kind::Box) return (hi_ - lo_).prod();
  const double h = hi_[2] - lo_[2];
  if (kind_ == Kind::Cone) return M_PI * h * (radius_ * radius_ + radius_ * radiusTop_ + radiusTop_ * radiusTop_) / 3;
  return M_PI * radius_ * radius_ * h;
}

}  // namespace parcelflow::cfd
