#include "krylov_solver.hpp"

#include <algorithm>
#include <cmath>

namespace parcelflow::cfd {

KrylovSolver::KrylovSolver(const LduMatrix& matrix, const LinearSolverSettings& settings,
                           ScalarField extraDiag)
    : matrix_(matrix),
      settings_(settings),
      extraDiag_(std::move(extraDiag)),
      precond_(makePreconditioner(matrix_, extraDiag_, settings_.preconditioner)) {}

KrylovSolver::KrylovSolver(const LduMatrix& matrix, const LinearSolverSettings& settings,
                           std::shared_ptr<const Preconditioner> precond)
    : matrix_(matrix), settings_(settings), precond_(std::move(precond)) {}

double KrylovSolver::dot(const ScalarField& a, const ScalarField& b) const {
  double local = 0.0;
  for (int c = 0; c < matrix_.mesh().nOwnedCells(); ++c) local += a[c] * b[c];
  return matrix_.mesh().sum(local);
}

void KrylovSolver::residual(ScalarField& x, const ScalarField& b, ScalarField& r) const {
  matrix_.multiply(x, r, extraDiag_);
  for (int c = 0; c < matrix_.mesh().nOwnedCells(); ++c) r[c] = b[c] - r[c];
}

SolveStats KrylovSolver::pcg(ScalarField& x, const ScalarField& b) const {
  const int nLocal = matrix_.mesh().nLocalCells(), nOwned = matrix_.mesh().nOwnedCells();
  const Preconditioner& precond = *precond_;
  ScalarField r(nLocal, 0.0), z(nLocal, 0.0), p(nLocal, 0.0), q(nLocal, 0.0);
  const double normB = std::sqrt(dot(b, b));
  const double scale = normB > 0.0 ? normB : 1.0;
  const double target = std::max(settings_.relTolerance * normB, settings_.absTolerance);
  residual(x, b, r);
  SolveStats stats;
  double normR = std::sqrt(dot(r, r));
  stats.initialResidual = normR / scale;
  double rz = 0.0;
  while (normR > target && stats.iterations < settings_.maxIterations) {
    precond.apply(r, z);
    const double rzNew = dot(r, z);
    const double beta = stats.iterations == 0 ? 0.0 : rzNew / rz;
    rz = rzNew;
    for (int c = 0; c < nOwned; ++c) p[c] = z[c] + beta * p[c];
    matrix_.multiply(p, q, extraDiag_);
    const double alpha = rz / dot(p, q);
    for (int c = 0; c < nOwned; ++c) {
      x[c] += alpha * p[c];
      r[c] -= alpha * q[c];
    }
    normR = std::sqrt(dot(r, r));
    ++stats.iterations;
  }
  stats.finalResidual = normR / scale;
  stats.converged = normR <= target;
  matrix_.mesh().exchange(x);
  return stats;
}

SolveStats KrylovSolver::bicgstab(ScalarField& x, const ScalarField& b) const {
  const int nLocal = matrix_.mesh().nLocalCells(), nOwned = matrix_.mesh().nOwnedCells();
  const Preconditioner& precond = *precond_;
  ScalarField r(nLocal, 0.0), r0(nLocal, 0.0), p(nLocal, 0.0), v(nLocal, 0.0), s(nLocal, 0.0),
      t(nLocal, 0.0), pHat(nLocal, 0.0), sHat(nLocal, 0.0);
  const double normB = std::sqrt(dot(b, b));
  const double scale = normB > 0.0 ? normB : 1.0;
  const double target = std::max(settings_.relTolerance * normB, settings_.absTolerance);
  residual(x, b, r);
  r0 = r;
  SolveStats stats;
  double normR = std::sqrt(dot(r, r));
  stats.initialResidual = normR / scale;
  double rho = 1.0, alpha = 1.0, omega = 1.0;
  while (normR > target && stats.iterations < settings_.maxIterations) {
    const double rhoNew = dot(r0, r);
    if (rhoNew == 0.0) break;  // breakdown: reported as not converged below
    const double beta = (rhoNew / rho) * (alpha / omega);
    rho = rhoNew;
    for (int c = 0; c < nOwned; ++c) p[c] = r[c] + beta * (p[c] - omega * v[c]);
    precond.apply(p, pHat);
    matrix_.multiply(pHat, v, extraDiag_);
    alpha = rho / dot(r0, v);
    for (int c = 0; c < nOwned; ++c) s[c] = r[c] - alpha * v[c];
    ++stats.iterations;
    const double normS = std::sqrt(dot(s, s));
    if (normS <= target) {
      for (int c = 0; c < nOwned; ++c) x[c] += alpha * pHat[c];
      normR = normS;
      break;
    }
    precond.apply(s, sHat);
    matrix_.multiply(sHat, t, extraDiag_);
    omega = dot(t, s) / dot(t, t);
    for (int c = 0; c < nOwned; ++c) {
      x[c] += alpha * pHat[c] + omega * sHat[c];
      r[c] = s[c] - omega * t[c];
    }
    normR = std::sqrt(dot(r, r));
    if (omega == 0.0) break;
  }
  stats.finalResidual = normR / scale;
  stats.converged = normR <= target;
  matrix_.mesh().exchange(x);
  return stats;
}

}  // namespace parcelflow::cfd
