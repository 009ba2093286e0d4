#include "cfd/linear/make_preconditioner.hpp"

#include "cfd/linear/block_jacobi_preconditioner.hpp"
#include "cfd/linear/boomeramg_preconditioner.hpp"

namespace parcelflow::cfd {

std::unique_ptr<Preconditioner> makePreconditioner(const LduMatrix& matrix,
                                                   const ScalarField& extraDiag,
                                                   PreconditionerType type) {
  if (type == PreconditionerType::BoomerAmg)
    return std::make_unique<BoomerAmgPreconditioner>(matrix, extraDiag);
  return std::make_unique<BlockJacobiPreconditioner>(matrix, extraDiag, type);
}

}  // namespace parcelflow::cfd
