#pragma once
// What the Krylov solvers need of a preconditioner: z = M^-1 r on owned cells, M fixed after
// construction. makePreconditioner builds the one a LinearSolverSettings names.
#include <memory>

#include "gas_settings.hpp"
#include "ldu_matrix.hpp"

namespace parcelflow::cfd {

class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  // r, z: local fields; only owned entries are read and written.
  virtual void apply(const ScalarField& r, ScalarField& z) const = 0;
};

// Collective for boomeramg. The preconditioner copies what it needs: it may outlive the matrix and
// extraDiag (ReusedPreconditioner keeps it over steps whose matrices come and go).
std::unique_ptr<Preconditioner> makePreconditioner(const LduMatrix& matrix,
                                                   const ScalarField& extraDiag,
                                                   PreconditionerType type);

}  // namespace parcelflow::cfd
