#pragma once
// Basic field types of the gas solver. Cell fields are indexed by local cell (owned cells first, then
// ghosts); face fields by local face.
#include <Eigen/Core>
#include <vector>

namespace parcelflow::cfd {

using Vec3 = Eigen::Vector3d;
using ScalarField = std::vector<double>;
using VectorField = std::vector<Vec3>;

// Axis of the largest component: the normal axis of a (staircase, axis-aligned) face area vector.
inline int dominantAxis(const Vec3& v) {
  int axis = 0;
  v.cwiseAbs().maxCoeff(&axis);
  return axis;
}

}  // namespace parcelflow::cfd
