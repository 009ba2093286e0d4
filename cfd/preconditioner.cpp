#include "preconditioner.hpp"

#include "block_jacobi_preconditioner.hpp"
#include "boomeramg_preconditioner.hpp"

namespace parcelflow::cfd {

std::unique_ptr<Preconditioner> makePreconditioner(const LduMatrix& matrix,
                                                   const ScalarField& extraDiag,
                                                   PreconditionerType type) {
  if (type == PreconditionerType::BoomerAmg)
    return std::make_unique<BoomerAmgPreconditioner>(matrix, extraDiag);
  return std::make_unique<BlockJacobiPreconditioner>(matrix, extraDiag, type);
}

}  // namespace parcelflow::cfd
