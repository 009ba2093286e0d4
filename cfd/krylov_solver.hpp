#pragma once
// Distributed Krylov methods over LduMatrix with a block-Jacobi or BoomerAMG preconditioner: PCG for
// the symmetric pressure equation, BiCGStab for the momentum components. Converged when the residual
// 2-norm is below max(relTolerance * |b|, absTolerance); a solve that hits maxIterations is reported,
// not hidden.
#include <memory>

#include "gas_settings.hpp"
#include "ldu_matrix.hpp"
#include "preconditioner.hpp"

namespace parcelflow::cfd {

struct SolveStats {
  int iterations = 0;
  double initialResidual = 0.0;  // |b - A x0| / |b|
  double finalResidual = 0.0;    // |b - A x| / |b|
  bool converged = true;
};

class KrylovSolver {
 public:
  // Sets up the preconditioner once (collective); solve as many right-hand sides as needed with it.
  // The matrix must outlive the solver and keep its coefficients.
  KrylovSolver(const LduMatrix& matrix, const LinearSolverSettings& settings,
               ScalarField extraDiag = {});
  // Uses a given preconditioner, e.g. one built for a nearby matrix of an earlier step: the solve
  // stays exact, only the iteration count depends on how well it fits.
  KrylovSolver(const LduMatrix& matrix, const LinearSolverSettings& settings,
               std::shared_ptr<const Preconditioner> precond);
  // x: local field (initial guess on owned cells, ghosts refreshed on return); b: owned right side.
  SolveStats pcg(ScalarField& x, const ScalarField& b) const;
  SolveStats bicgstab(ScalarField& x, const ScalarField& b) const;

 private:
  double dot(const ScalarField& a, const ScalarField& b) const;
  void residual(ScalarField& x, const ScalarField& b, ScalarField& r) const;
  const LduMatrix& matrix_;
  LinearSolverSettings settings_;
  ScalarField extraDiag_;
  std::shared_ptr<const Preconditioner> precond_;
};

}  // namespace parcelflow::cfd
