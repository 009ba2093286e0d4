#include "coupling/transfer/background_grid.hpp"

#include <stdexcept>
#include <string>

#include "cfd/base/internal_error.hpp"

namespace parcelflow::coupling {

void BackgroundGrid::validate() const {
  for (int d = 0; d < 3; ++d) {
    PARCELFLOW_ASSERT(spacing[d] > 0.0, "background grid: spacing along axis " + std::to_string(d) +
                                            " must be > 0, got " + std::to_string(spacing[d]));
    PARCELFLOW_ASSERT(cells[d] > 0, "background grid: cell count along axis " + std::to_string(d) +
                                        " must be > 0, got " + std::to_string(cells[d]));
  }
}

}  // namespace parcelflow::coupling
