#pragma once
// Fluid region = ordered unions and cut-outs of primitives, applied in list order (an empty list means
// the whole background box is fluid). Wall faces facing a solid cell are named after the last cut-out
// containing that cell's centre when it has a `patch` name, otherwise "walls".
#include <string>
#include <vector>

#include "cfd/geometry/primitive.hpp"

namespace parcelflow::cfd {

class Geometry {
 public:
  enum class Op { Union, Cut };
  struct Item {
    Op op;
    Primitive primitive;
    std::string patch;  // wall patch name for faces towards solid cells inside a cut ("" = walls)
  };

  Geometry() = default;
  explicit Geometry(std::vector<Item> items) : items_(std::move(items)) {}

  bool isFluid(const Vec3& x) const;
  std::string wallPatchAt(const Vec3& solidCellCentre) const;
  const std::vector<Item>& items() const { return items_; }

  static constexpr const char* defaultWallPatch = "walls";

 private:
  std::vector<Item> items_;
};

}  // namespace parcelflow::cfd
