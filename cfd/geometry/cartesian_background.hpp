#pragma once
// The Cartesian background grid the mesh is cut from: `n` cells per axis of uniform spacing per axis,
// starting at `origin`. Background index (i, j, k), linear index i + n0 (j + n1 k).
#include <array>
#include <cmath>

#include "cfd/base/types.hpp"

namespace parcelflow::cfd {

// A coordinate within this share of a spacing of a grid plane is on it: the cut-cell geometry moves surface
// points there onto the plane (MFiX's TOL_SNAP idea), and planesNearCellFaces reports only planes further off.
constexpr double kOnGridPlane = 1e-9;

class CartesianBackground {
 public:
  CartesianBackground() = default;
  CartesianBackground(const Vec3& origin, const Vec3& lengths, const std::array<int, 3>& n)
      : origin_(origin), n_(n) {
    for (int d = 0; d < 3; ++d) spacing_[d] = lengths[d] / n[d];
  }

  const Vec3& origin() const { return origin_; }
  const Vec3& spacing() const { return spacing_; }
  const std::array<int, 3>& n() const { return n_; }
  long size() const { return static_cast<long>(n_[0]) * n_[1] * n_[2]; }
  bool inside(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < n_[0] && j < n_[1] && k < n_[2];
  }
  long index(int i, int j, int k) const {
    return i + static_cast<long>(n_[0]) * (j + static_cast<long>(n_[1]) * k);
  }
  std::array<int, 3> ijk(long index) const {
    const int i = static_cast<int>(index % n_[0]);
    const long rest = index / n_[0];
    return {i, static_cast<int>(rest % n_[1]), static_cast<int>(rest / n_[1])};
  }
  Vec3 centre(int i, int j, int k) const {
    return origin_ + Vec3((i + 0.5) * spacing_[0], (j + 0.5) * spacing_[1], (k + 0.5) * spacing_[2]);
  }
  double cellVolume() const { return spacing_.prod(); }
  // The grid plane nearest to x along `axis` and how far x lies off it, in spacings (kOnGridPlane: on it).
  struct NearestPlane {
    long plane;
    double offSpacings;
  };
  NearestPlane nearestPlane(int axis, double x) const {
    const double t = (x - origin_[axis]) / spacing_[axis];
    const double plane = std::round(t);
    return {static_cast<long>(plane), std::abs(t - plane)};
  }
  // Grid plane n along `axis` lies at origin + n spacing.
  double planeCoordinate(int axis, long plane) const { return origin_[axis] + plane * spacing_[axis]; }

 private:
  Vec3 origin_ = Vec3::Zero();
  Vec3 spacing_ = Vec3::Ones();
  std::array<int, 3> n_{1, 1, 1};
};

}  // namespace parcelflow::cfd
