#include "cfd/linear/block_jacobi_preconditioner.hpp"

#include "cfd/base/internal_error.hpp"

namespace parcelflow::cfd {

BlockJacobiPreconditioner::BlockJacobiPreconditioner(const LduMatrix& matrix,
                                                     const ScalarField& extraDiag,
                                                     PreconditionerType type)
    : type_(type), nOwned_(matrix.mesh().nOwnedCells()) {
  if (type_ == PreconditionerType::Jacobi) {
    inverseDiag_.resize(nOwned_);
    for (int c = 0; c < nOwned_; ++c) {
      const double d = matrix.diag()[c] + (extraDiag.empty() ? 0.0 : extraDiag[c]);
      PARCELFLOW_ASSERT(d != 0.0, "zero diagonal in a gas matrix");
      inverseDiag_[c] = 1.0 / d;
    }
    return;
  }
  const auto block = matrix.localBlock(extraDiag);
  if (type_ == PreconditionerType::BlockIncompleteCholesky) {
    ic_ = std::make_unique<Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>>>();
    ic_->compute(block);
    PARCELFLOW_ASSERT(ic_->info() == Eigen::Success, "incomplete Cholesky failed");
  } else {
    ldlt_ = std::make_unique<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>();
    ldlt_->compute(block);
    PARCELFLOW_ASSERT(ldlt_->info() == Eigen::Success, "block Cholesky failed");
  }
}

void BlockJacobiPreconditioner::apply(const ScalarField& r, ScalarField& z) const {
  if (type_ == PreconditionerType::Jacobi) {
    for (int c = 0; c < nOwned_; ++c) z[c] = inverseDiag_[c] * r[c];
    return;
  }
  const Eigen::Map<const Eigen::VectorXd> rv(r.data(), nOwned_);
  Eigen::Map<Eigen::VectorXd> zv(z.data(), nOwned_);
  if (ic_)
    zv = ic_->solve(rv);
  else
    zv = ldlt_->solve(rv);
}

}  // namespace parcelflow::cfd
