#include "centroid_kernel.hpp"

#include <stdexcept>
#include <string>

namespace parcelflow::coupling {

CentroidKernel::CentroidKernel(int searchRadius) : r_(searchRadius) {
  if (searchRadius < 0 || searchRadius > maxSearchRadius)
    throw std::invalid_argument("centroid kernel: fallback search radius must be in [0, " +
                                std::to_string(maxSearchRadius) + "] cells, got " +
                                std::to_string(searchRadius));
}

}  // namespace parcelflow::coupling
