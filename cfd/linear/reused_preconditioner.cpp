#include "cfd/linear/reused_preconditioner.hpp"

#include <algorithm>

#include "cfd/base/internal_error.hpp"
#include "cfd/linear/make_preconditioner.hpp"

namespace parcelflow::cfd {

namespace {
// A build's cost in PCG iterations with the built preconditioner, measured on the Goldschmidt mesh
// (22,090 cells, 1 rank; tests/benchmarks/cfd and a coupled run): BoomerAMG's setup 16.6-20.5 ms
// against 0.89-0.97 ms per iteration; block_ic 16.8 ms against 0.48 ms; block_cholesky 133 ms
// against 4.2 ms.
int setupCostInIterations(PreconditionerType type) {
  switch (type) {
    case PreconditionerType::BoomerAmg: return 20;
    case PreconditionerType::BlockIncompleteCholesky: return 35;
    case PreconditionerType::BlockCholesky: return 30;
    case PreconditionerType::Jacobi: return 1;
  }
  PARCELFLOW_ASSERT(false, "unknown preconditioner type");
  return 1;
}
}  // namespace

ReusedPreconditioner::ReusedPreconditioner(PreconditionerType type, int maxSteps)
    : type_(type), maxSteps_(maxSteps) {
  PARCELFLOW_ASSERT(maxSteps >= 1, "a preconditioner must serve at least one step");
}

std::shared_ptr<const Preconditioner> ReusedPreconditioner::forStep(const LduMatrix& matrix) {
  if (!precond_ || age_ >= maxSteps_ || excessIterations_ >= setupCostInIterations(type_)) {
    precond_ = makePreconditioner(matrix, {}, type_);
    age_ = 0;
    freshIterations_.clear();
    excessIterations_ = 0;
  }
  ++age_;
  solve_ = 0;
  return precond_;
}

void ReusedPreconditioner::recordIterations(int iterations) {
  if (age_ == 1)
    freshIterations_.push_back(iterations);
  else if (solve_ < freshIterations_.size())
    excessIterations_ += std::max(0, iterations - freshIterations_[solve_]);
  ++solve_;
}

}  // namespace parcelflow::cfd
