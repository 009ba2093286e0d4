#include "cfd/fv/diffusion_smoother.hpp"

#include <string>

#include "cfd/fv/fvm.hpp"
#include "cfd/base/internal_error.hpp"

namespace parcelflow::cfd {

namespace {
LinearSolverSettings smootherSolve() {
  LinearSolverSettings s;
  s.relTolerance = 1e-12;
  s.absTolerance = 1e-300;
  s.maxIterations = 1000;
  s.preconditioner = PreconditionerType::BlockIncompleteCholesky;
  return s;
}
}  // namespace

DiffusionSmoother::DiffusionSmoother(const Mesh& mesh, double length)
    : mesh_(mesh), length_(length), matrix_(mesh), x_(mesh.nLocalCells(), 0.0), b_(mesh.nOwnedCells(), 0.0) {
  PARCELFLOW_ASSERT(length > 0.0, "diffusion smoother: length must be > 0, got " + std::to_string(length));
  fvm::laplacian(matrix_, ScalarField(mesh.nInternalFaces(), length * length));
  for (int c = 0; c < mesh.nOwnedCells(); ++c) matrix_.diag()[c] += mesh.cellVolume(c);
  solver_ = std::make_unique<KrylovSolver>(matrix_, smootherSolve());
}

SolveStats DiffusionSmoother::apply(std::vector<double>& owned) {
  const int n = mesh_.nOwnedCells();
  PARCELFLOW_ASSERT(static_cast<int>(owned.size()) == n, "diffusion smoother: field is not on the owned cells");
  for (int c = 0; c < n; ++c) {
    b_[c] = mesh_.cellVolume(c) * owned[c];
    x_[c] = owned[c];  // the unsmoothed field as the first guess
  }
  const SolveStats stats = solver_->pcg(x_, b_);
  PARCELFLOW_ASSERT(stats.converged, "diffusion smoother: PCG did not converge in " +
                                         std::to_string(stats.iterations) + " iterations");
  for (int c = 0; c < n; ++c) owned[c] = x_[c];
  return stats;
}

}  // namespace parcelflow::cfd
