#pragma once
// The preconditioner of a PreconditionerType: block Jacobi (point, incomplete or exact Cholesky blocks) or
// BoomerAMG. Apart from preconditioner.hpp so that the interface does not know its implementations.
#include <memory>

#include "cfd/linear/ldu_matrix.hpp"
#include "cfd/linear/linear_solver_settings.hpp"
#include "cfd/linear/preconditioner.hpp"

namespace parcelflow::cfd {

// Collective for boomeramg. The preconditioner copies what it needs: it may outlive the matrix and
// extraDiag (ReusedPreconditioner keeps it over steps whose matrices come and go).
std::unique_ptr<Preconditioner> makePreconditioner(const LduMatrix& matrix,
                                                   const ScalarField& extraDiag,
                                                   PreconditionerType type);

}  // namespace parcelflow::cfd
