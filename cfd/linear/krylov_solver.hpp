#pragma once
// Distributed Krylov methods over LduMatrix with a block-Jacobi or BoomerAMG preconditioner: PCG for
// the symmetric pressure equation, BiCGStab for the momentum components. Each solve stops by a
// StoppingRule (strict: the residual 2-norm relative to |b|; normalized: the residual 1-norm over a
// normalization, OpenFOAM-style; see LinearSolverSettings); a solve that hits maxIterations is
// reported, not hidden.
#include <memory>

#include "cfd/linear/linear_solver_settings.hpp"
#include "cfd/linear/ldu_matrix.hpp"
#include "cfd/linear/preconditioner.hpp"

namespace parcelflow::cfd {

struct SolveStats {
  int iterations = 0;
  double initialResidual = 0.0;  // strict: |b - A x0|_2 / |b|_2; normalized: |b - A x0|_1 / normalization
  double finalResidual = 0.0;    // the same measure at the end
  bool converged = true;
};

// When one solve stops.
struct StoppingRule {
  StoppingCriterion criterion = StoppingCriterion::Strict;
  double tolerance = 1e-8;         // strict: relative to |b|_2; normalized: on the normalized residual
  double absoluteTolerance = 0.0;  // strict: on |r|_2
  double relTol = 0.0;             // normalized: or this fraction of the initial normalized residual
  // Normalized: what |r|_1 is divided by; 0 = OpenFOAM's sum|A x0 - A xbar| + sum|b - A xbar| (xbar the
  // mean of the initial guess), which measures the residual against the variation of the solution.
  double normalization = 0.0;
};

// The rule the settings give a solve: `lastCorrector` selects finalRelTol (the last PISO corrector's
// pressure solve), `normalization` as in StoppingRule (ignored by the strict criterion).
StoppingRule stoppingRule(const LinearSolverSettings& settings, bool lastCorrector = false,
                          double normalization = 0.0);
// The strict rule with the settings' relTolerance and absTolerance, whatever their criterion.
StoppingRule strictRule(const LinearSolverSettings& settings);

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
  SolveStats pcg(ScalarField& x, const ScalarField& b, const StoppingRule& rule) const;
  SolveStats bicgstab(ScalarField& x, const ScalarField& b, const StoppingRule& rule) const;
  // With the settings' rule (stoppingRule(settings)).
  SolveStats pcg(ScalarField& x, const ScalarField& b) const;
  SolveStats bicgstab(ScalarField& x, const ScalarField& b) const;
  // |b - A x|_1 over all ranks (collective; refreshes x's ghosts).
  double residualOneNorm(ScalarField& x, const ScalarField& b) const;

 private:
  // The norm a rule measures residuals with, what it divides them by, and where the solve stops.
  struct Stop {
    bool oneNorm = false;
    double scale = 1.0;
    double target = 0.0;  // on the unscaled norm
  };
  Stop stopFor(const StoppingRule& rule, const ScalarField& x, const ScalarField& b, const ScalarField& r0) const;
  double openFoamNormalization(const ScalarField& x, const ScalarField& b, const ScalarField& r0) const;
  double norm(const ScalarField& r, bool oneNorm) const;
  double dot(const ScalarField& a, const ScalarField& b) const;
  void residual(ScalarField& x, const ScalarField& b, ScalarField& r) const;
  const LduMatrix& matrix_;
  LinearSolverSettings settings_;
  ScalarField extraDiag_;
  std::shared_ptr<const Preconditioner> precond_;
};

}  // namespace parcelflow::cfd
