#include "cfd/geometry/geometry.hpp"

namespace parcelflow::cfd {

bool Geometry::isFluid(const Vec3& x) const {
  if (items_.empty()) return true;
  bool fluid = false;
  for (const auto& item : items_) {
    if (item.op == Op::Union)
      fluid = fluid || item.primitive.contains(x);
    else if (item.primitive.contains(x))
      fluid = false;
  }
  return fluid;
}

std::string Geometry::wallPatchAt(const Vec3& solidCellCentre) const {
  std::string name = defaultWallPatch;
  for (const auto& item : items_)
    if (item.op == Op::Cut && !item.patch.empty() && item.primitive.contains(solidCellCentre))
      name = item.patch;
  return name;
}

}  // namespace parcelflow::cfd
