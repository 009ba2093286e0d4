#include "gaussian_kernel.hpp"

#include <stdexcept>
#include <string>

namespace parcelflow::coupling {

GaussianKernel::GaussianKernel(double sharpness, int radius)
    : a_(sharpness), r_(radius), expMinus2a_(std::exp(-2.0 * sharpness)) {
  if (!(sharpness > 0.0) || !std::isfinite(sharpness))
    throw std::invalid_argument("gaussian kernel: sharpness a must be > 0, got " + std::to_string(sharpness));
  if (radius < 0 || radius > maxRadius)
    throw std::invalid_argument("gaussian kernel: stencil radius must be in [0, " + std::to_string(maxRadius) +
                                "] cells, got " + std::to_string(radius));
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
