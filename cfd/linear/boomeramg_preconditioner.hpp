#pragma once
// One V-cycle of hypre's BoomerAMG (algebraic multigrid) as the preconditioner of our PCG, over all
// ranks at once. Unlike block-Jacobi it keeps the couplings between ranks and removes the smooth error
// on coarse grids, so PCG needs far fewer iterations (Goldschmidt mesh: 18 instead of 540 per step).
// Our own PCG, not hypre's, runs the iterations: the convergence test, the statistics and the
// unconverged-solve count stay the same for every preconditioner.
#include <HYPRE_parcsr_ls.h>

#include <memory>
#include <type_traits>

#include "cfd/linear/hypre_matrix.hpp"
#include "cfd/linear/hypre_vector.hpp"
#include "cfd/linear/preconditioner.hpp"

namespace parcelflow::cfd {

class BoomerAmgPreconditioner : public Preconditioner {
 public:
  // Builds the multigrid hierarchy (collective). Needs a symmetric positive definite matrix.
  BoomerAmgPreconditioner(const LduMatrix& matrix, const ScalarField& extraDiag);
  // Collective: every rank calls it with its own r.
  void apply(const ScalarField& r, ScalarField& z) const override;

 private:
  HypreMatrix matrix_;
  // The V-cycle's right-hand side and result; hypre writes into them even in a const apply.
  mutable HypreVector rhs_, solution_;
  std::unique_ptr<std::remove_pointer_t<HYPRE_Solver>, decltype(&HYPRE_BoomerAMGDestroy)> amg_{
      nullptr, &HYPRE_BoomerAMGDestroy};
};

}  // namespace parcelflow::cfd
