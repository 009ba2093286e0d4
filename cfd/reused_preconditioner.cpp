#include "reused_preconditioner.hpp"

#include "internal_error.hpp"

namespace parcelflow::cfd {

ReusedPreconditioner::ReusedPreconditioner(PreconditionerType type, int maxSteps)
    : type_(type), maxSteps_(maxSteps) {
  PARCELFLOW_ASSERT(maxSteps >= 1, "a preconditioner must serve at least one step");
}

std::shared_ptr<const Preconditioner> ReusedPreconditioner::forStep(const LduMatrix& matrix) {
  if (!precond_ || age_ >= maxSteps_ || outgrown_) {
    precond_ = makePreconditioner(matrix, {}, type_);
    age_ = 0;
    freshIterations_ = -1;
    outgrown_ = false;
  }
  ++age_;
  return precond_;
}

void ReusedPreconditioner::recordIterations(int iterations) {
  if (freshIterations_ < 0)
    freshIterations_ = iterations;
  else if (iterations > 2 * freshIterations_ + 2)
    outgrown_ = true;
}

}  // namespace parcelflow::cfd
