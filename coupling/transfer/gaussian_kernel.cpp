#include "coupling/transfer/gaussian_kernel.hpp"

#include <stdexcept>
#include <string>

#include "cfd/base/internal_error.hpp"

namespace parcelflow::coupling {

GaussianKernel::GaussianKernel(double sharpness, int radius) : a_(sharpness), r_(radius) {
  // The case reader has checked both (coupling.kernel): a failure here is a bug.
  PARCELFLOW_ASSERT(sharpness > 0.0 && std::isfinite(sharpness),
                    "gaussian kernel: sharpness a must be > 0, got " + std::to_string(sharpness));
  PARCELFLOW_ASSERT(radius >= 0 && radius <= maxRadius, "gaussian kernel: stencil radius must be in [0, " +
                                                            std::to_string(maxRadius) + "] cells, got " +
                                                            std::to_string(radius));
  for (int d = 0; d < 3; ++d) {
    axisA_[d] = sharpness;
    expMinus2a_[d] = std::exp(-2.0 * sharpness);
  }
}

GaussianKernel::GaussianKernel(double sharpness, int radius, const double (&spacing)[3])
    : GaussianKernel(sharpness, radius) {
  PARCELFLOW_ASSERT(spacing[0] > 0.0 && spacing[1] > 0.0 && spacing[2] > 0.0,
                    "gaussian kernel: cell lengths must be > 0");
  const double h = std::cbrt(spacing[0] * spacing[1] * spacing[2]);
  isotropicLength_ = h;
  for (int d = 0; d < 3; ++d) {
    // exactly a on cubic cells, whatever the rounding of the cube root
    const double ratio = spacing[0] == spacing[1] && spacing[1] == spacing[2] ? 1.0 : spacing[d] / h;
    axisA_[d] = sharpness * ratio * ratio;
    expMinus2a_[d] = std::exp(-2.0 * axisA_[d]);
  }
}

GaussianKernel::GaussianKernel(double sharpness, int radius, const double (&spacing)[3], bool isotropic,
                               double parcelFactor, bool reflectAtWalls)
    : GaussianKernel(isotropic ? GaussianKernel(sharpness, radius, spacing) : GaussianKernel(sharpness, radius)) {
  PARCELFLOW_ASSERT(parcelFactor >= 0.0 && std::isfinite(parcelFactor),
                    "gaussian kernel: parcel factor must be >= 0, got " + std::to_string(parcelFactor));
  parcelFactor_ = parcelFactor;
  reflect_ = reflectAtWalls;
}

double GaussianKernel::retainedMassFraction1D(double sharpness, int radius, double offset) {
  // cells m = ..., -1, 0, 1, ... relative to the parcel's cell; distance (m - offset) cell lengths.
  double inside = 0.0, all = 0.0;
  for (int m = -60; m <= 60; ++m) {
    const double t = m - offset;
    const double w = std::exp(-sharpness * t * t);
    all += w;
    if (m >= -radius && m <= radius) inside += w;
  }
  return inside / all;
}

}  // namespace parcelflow::coupling
