#include "cfd/linear/krylov_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cfd/linear/make_preconditioner.hpp"

namespace parcelflow::cfd {

StoppingRule stoppingRule(const LinearSolverSettings& settings, bool lastCorrector, double normalization) {
  if (settings.criterion == StoppingCriterion::Strict) return strictRule(settings);
  StoppingRule rule;
  rule.criterion = StoppingCriterion::Normalized;
  rule.tolerance = settings.tolerance;
  rule.relTol = lastCorrector ? settings.finalRelTol : settings.relTol;
  rule.normalization = normalization;
  return rule;
}

StoppingRule strictRule(const LinearSolverSettings& settings) {
  StoppingRule rule;
  rule.tolerance = settings.relTolerance;
  rule.absoluteTolerance = settings.absTolerance;
  return rule;
}

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

double KrylovSolver::norm(const ScalarField& r, bool oneNorm) const {
  if (!oneNorm) return std::sqrt(dot(r, r));
  double local = 0.0;
  for (int c = 0; c < matrix_.mesh().nOwnedCells(); ++c) local += std::abs(r[c]);
  return matrix_.mesh().sum(local);
}

double KrylovSolver::openFoamNormalization(const ScalarField& x, const ScalarField& b, const ScalarField& r0) const {
  // sum|A x - A xbar| + sum|b - A xbar|: a uniform shift of the solution changes neither term, so the
  // rule asks for the same accuracy whatever the field's mean (a uniform gas velocity). A x = b - r0.
  const Mesh& m = matrix_.mesh();
  double local = 0.0;
  for (int c = 0; c < m.nOwnedCells(); ++c) local += x[c];
  ScalarField xbar(m.nLocalCells(), m.sum(local) / m.nGlobalCells()), aXbar(m.nLocalCells(), 0.0);
  matrix_.multiply(xbar, aXbar, extraDiag_);
  local = 0.0;
  for (int c = 0; c < m.nOwnedCells(); ++c)
    local += std::abs(b[c] - r0[c] - aXbar[c]) + std::abs(b[c] - aXbar[c]);
  return m.sum(local);
}

KrylovSolver::Stop KrylovSolver::stopFor(const StoppingRule& rule, const ScalarField& x, const ScalarField& b,
                                         const ScalarField& r0) const {
  if (rule.criterion == StoppingCriterion::Strict) {
    const double normB = norm(b, false);
    return {false, normB > 0.0 ? normB : 1.0, std::max(rule.tolerance * normB, rule.absoluteTolerance)};
  }
  // A zero normalization (nothing flows, b = 0) leaves the smallest positive scale: then only r = 0 stops.
  const double n = rule.normalization > 0.0 ? rule.normalization : openFoamNormalization(x, b, r0);
  const double scale = std::max(n, std::numeric_limits<double>::min());
  return {true, scale, std::max(rule.tolerance * scale, rule.relTol * norm(r0, true))};
}

SolveStats KrylovSolver::pcg(ScalarField& x, const ScalarField& b) const {
  return pcg(x, b, stoppingRule(settings_));
}

SolveStats KrylovSolver::bicgstab(ScalarField& x, const ScalarField& b) const {
  return bicgstab(x, b, stoppingRule(settings_));
}

void KrylovSolver::residual(ScalarField& x, const ScalarField& b, ScalarField& r) const {
  matrix_.multiply(x, r, extraDiag_);
  for (int c = 0; c < matrix_.mesh().nOwnedCells(); ++c) r[c] = b[c] - r[c];
}

double KrylovSolver::residualOneNorm(ScalarField& x, const ScalarField& b) const {
  ScalarField r(matrix_.mesh().nLocalCells(), 0.0);
  residual(x, b, r);
  return norm(r, true);
}

SolveStats KrylovSolver::pcg(ScalarField& x, const ScalarField& b, const StoppingRule& rule) const {
  const int nLocal = matrix_.mesh().nLocalCells(), nOwned = matrix_.mesh().nOwnedCells();
  const Preconditioner& precond = *precond_;
  ScalarField r(nLocal, 0.0), z(nLocal, 0.0), p(nLocal, 0.0), q(nLocal, 0.0);
  residual(x, b, r);
  const Stop stop = stopFor(rule, x, b, r);
  const double scale = stop.scale, target = stop.target;
  SolveStats stats;
  double normR = norm(r, stop.oneNorm);
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
    normR = norm(r, stop.oneNorm);
    ++stats.iterations;
  }
  stats.finalResidual = normR / scale;
  stats.converged = normR <= target;
  matrix_.mesh().exchange(x);
  return stats;
}

SolveStats KrylovSolver::bicgstab(ScalarField& x, const ScalarField& b, const StoppingRule& rule) const {
  const int nLocal = matrix_.mesh().nLocalCells(), nOwned = matrix_.mesh().nOwnedCells();
  const Preconditioner& precond = *precond_;
  ScalarField r(nLocal, 0.0), r0(nLocal, 0.0), p(nLocal, 0.0), v(nLocal, 0.0), s(nLocal, 0.0),
      t(nLocal, 0.0), pHat(nLocal, 0.0), sHat(nLocal, 0.0);
  residual(x, b, r);
  r0 = r;
  const Stop stop = stopFor(rule, x, b, r);
  const double scale = stop.scale, target = stop.target;
  SolveStats stats;
  double normR = norm(r, stop.oneNorm);
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
    const double normS = norm(s, stop.oneNorm);
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
    normR = norm(r, stop.oneNorm);
    if (omega == 0.0) break;
  }
  stats.finalResidual = normR / scale;
  stats.converged = normR <= target;
  matrix_.mesh().exchange(x);
  return stats;
}

}  // namespace parcelflow::cfd
