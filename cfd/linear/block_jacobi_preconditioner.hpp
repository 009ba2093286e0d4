#pragma once
// Block-Jacobi preconditioner: each rank applies an Eigen factorisation of its owned block (couplings
// to other ranks are dropped), or plain Jacobi. The Cholesky variants need a symmetric positive
// definite matrix (the pressure equation).
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <memory>

#include "cfd/linear/linear_solver_settings.hpp"
#include "cfd/linear/ldu_matrix.hpp"
#include "cfd/linear/preconditioner.hpp"

namespace parcelflow::cfd {

class BlockJacobiPreconditioner : public Preconditioner {
 public:
  BlockJacobiPreconditioner(const LduMatrix& matrix, const ScalarField& extraDiag,
                            PreconditionerType type);
  // z = M^-1 r on owned entries.
  void apply(const ScalarField& r, ScalarField& z) const override;

 private:
  PreconditionerType type_;
  int nOwned_;
  ScalarField inverseDiag_;
  std::unique_ptr<Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>>> ic_;
  std::unique_ptr<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> ldlt_;
};

}  // namespace parcelflow::cfd
