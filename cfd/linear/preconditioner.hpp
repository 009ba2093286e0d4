#pragma once
// What the Krylov solvers need of a preconditioner: z = M^-1 r on owned cells, M fixed after
// construction. makePreconditioner (make_preconditioner.hpp) builds the one a LinearSolverSettings names.
#include "cfd/linear/ldu_matrix.hpp"

namespace parcelflow::cfd {

class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  // r, z: local fields; only owned entries are read and written.
  virtual void apply(const ScalarField& r, ScalarField& z) const = 0;
};

}  // namespace parcelflow::cfd
