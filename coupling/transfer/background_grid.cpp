#include "background_grid.hpp"

#include <stdexcept>
#include <string>

namespace parcelflow::coupling {

void BackgroundGrid::validate() const {
  for (int d = 0; d < 3; ++d) {
    if (!(spacing[d] > 0.0))
      throw std::invalid_argument("background grid: spacing along axis " + std::to_string(d) +
                                  " must be > 0, got " + std::to_string(spacing[d]));
    if (cells[d] <= 0)
      throw std::invalid_argument("background grid: cell count along axis " + std::to_string(d) +
                                  " must be > 0, got " + std::to_string(cells[d]));
  }
}

}  // namespace parcelflow::coupling
