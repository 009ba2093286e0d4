#pragma once
// A solid given by its closed surface (an STL file of case.yaml's `geometry:`), with the inside test the
// staircase mesh and the regions need: a cell is fluid when its centre is inside (points on the surface
// count as inside, as on a box's faces). The test is CGAL's (ray shooting against an AABB tree built once,
// exact predicates); the cut-cell geometry takes the triangles themselves.
#include <memory>
#include <string>

#include "cfd/geometry/triangle_surface.hpp"

namespace parcelflow::cfd {

class SolidSurface {
 public:
  // Reads and checks `path` (stl_reader.hpp); `key` names the setting in messages.
  static std::shared_ptr<const SolidSurface> fromStl(const std::string& path, const std::string& key);
  explicit SolidSurface(TriangleSurface surface);
  ~SolidSurface();
  SolidSurface(const SolidSurface&) = delete;
  SolidSurface& operator=(const SolidSurface&) = delete;

  bool contains(const Vec3& x) const;
  const TriangleSurface& triangles() const { return surface_; }
  const Vec3& lo() const { return lo_; }  // bounding box
  const Vec3& hi() const { return hi_; }

 private:
  struct InsideTest;
  TriangleSurface surface_;
  Vec3 lo_, hi_;
  std::unique_ptr<InsideTest> inside_;
};

}  // namespace parcelflow::cfd
