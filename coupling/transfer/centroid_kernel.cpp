#include "coupling/transfer/centroid_kernel.hpp"

#include <stdexcept>
#include <string>

#include "cfd/base/internal_error.hpp"

namespace parcelflow::coupling {

CentroidKernel::CentroidKernel(int searchRadius) : r_(searchRadius) {
  PARCELFLOW_ASSERT(searchRadius >= 0 && searchRadius <= maxSearchRadius,
                    "centroid kernel: fallback search radius must be in [0, " + std::to_string(maxSearchRadius) +
                        "] cells, got " + std::to_string(searchRadius));
}

}  // namespace parcelflow::coupling
