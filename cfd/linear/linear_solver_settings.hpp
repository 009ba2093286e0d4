#pragma once
// What one linear solve is set up with: the preconditioner, its reuse over steps and when the solve stops.
// The gas solver's settings hold one of these per equation (solver/gas_settings.hpp).

namespace parcelflow::cfd {

enum class PreconditionerType { Jacobi, BlockIncompleteCholesky, BlockCholesky, BoomerAmg };

// When a linear solve stops (cfd/README.md, "Stopping the linear solves").
//   Strict: |r|_2 <= max(relTolerance |b|_2, absTolerance) on every solve.
//   Normalized (OpenFOAM's PISO practice): |r|_1 / n <= max(tolerance, relTol * initial |r|_1 / n), with
//   relTol = finalRelTol for the last PISO corrector's pressure solve. The normalization n is the step's gas
//   flow for the pressure (GasSolver::flowScale; the residual is the step's continuity error) and OpenFOAM's
//   sum|A x0 - A xbar| + sum|b - A xbar| for the momentum components.
enum class StoppingCriterion { Strict, Normalized };

struct LinearSolverSettings {
  double relTolerance = 1e-8;   // strict: on the residual 2-norm relative to the right-hand side's
  double absTolerance = 1e-30;  // strict: on the residual 2-norm
  int maxIterations = 1000;
  PreconditionerType preconditioner = PreconditionerType::BlockIncompleteCholesky;
  int preconditionerReuse = 1;  // gas steps one preconditioner serves at most (reused_preconditioner.hpp)
  StoppingCriterion criterion = StoppingCriterion::Strict;
  double tolerance = 1e-6;    // normalized: on the normalized residual
  double relTol = 0.0;        // normalized: fraction of the initial residual (0 = off)
  double finalRelTol = 0.0;   // normalized, pressure: relTol of the last PISO corrector
};

}  // namespace parcelflow::cfd
