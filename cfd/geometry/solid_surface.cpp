#include "cfd/geometry/solid_surface.hpp"

#include <CGAL/Side_of_triangle_mesh.h>

#include "cfd/geometry/cgal_surface_mesh.hpp"
#include "cfd/geometry/stl_reader.hpp"

namespace parcelflow::cfd {

struct SolidSurface::InsideTest {
  explicit InsideTest(const TriangleSurface& s) : mesh(cgal::toMesh(s)), side(mesh) {}
  cgal::Mesh mesh;  // before `side`, which keeps a reference to it
  CGAL::Side_of_triangle_mesh<cgal::Mesh, cgal::Kernel> side;
};

std::shared_ptr<const SolidSurface> SolidSurface::fromStl(const std::string& path, const std::string& key) {
  return std::make_shared<const SolidSurface>(readStlSurface(path, key));
}

SolidSurface::SolidSurface(TriangleSurface surface)
    : surface_(std::move(surface)), inside_(std::make_unique<InsideTest>(surface_)) {
  lo_ = hi_ = surface_.points.front();
  for (const auto& p : surface_.points) {
    lo_ = lo_.cwiseMin(p);
    hi_ = hi_.cwiseMax(p);
  }
}

SolidSurface::~SolidSurface() = default;

bool SolidSurface::contains(const Vec3& x) const {
  return inside_->side(cgal::toPoint(x)) != CGAL::ON_UNBOUNDED_SIDE;
}

}  // namespace parcelflow::cfd
