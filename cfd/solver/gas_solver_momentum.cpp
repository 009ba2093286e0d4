// GasSolver: momentum assembly and predictor (implicit Euler, upwind-biased convection).
#include <cmath>

#include "cfd/fv/fvc.hpp"
#include "cfd/fv/fvm.hpp"
#include "cfd/solver/gas_solver.hpp"
#include "cfd/base/internal_error.hpp"
#include "cfd/linear/krylov_solver.hpp"

namespace parcelflow::cfd {


VectorField GasSolver::boundaryVelocity() const {
  const Mesh& m = *mesh_;
  VectorField ub(m.nBoundaryFaces(), Vec3::Zero());
  for (int b = 0; b < m.nBoundaryFaces(); ++b) {
    const int c = m.boundaryCell(b);
    const auto& pc = patch_[m.boundaryPatch(b)];
    const Vec3 n = m.boundaryArea(b) / m.boundaryMagArea(b);
    switch (pc.type) {
      case BoundaryType::NoSlipWall: break;
      case BoundaryType::FreeSlipWall: ub[b] = U_[c] - U_[c].dot(n) * n; break;
      // Interstitial velocity at the face: superficial / a_g of the face (taken from the cell).
      case BoundaryType::VelocityInlet:
        // A distributor's faces carry the flux the last pressure correction gave them.
        ub[b] = (pc.resistance > 0.0 ? (phiB_[b] / m.boundaryMagArea(b)) * n : pc.scale * pc.superficialVelocity) /
                alpha_[c];
        break;
      case BoundaryType::PressureOutlet: ub[b] = U_[c]; break;
    }
  }
  return ub;
}

ScalarField GasSolver::boundaryPressure() const {
  // p_rgh on boundary faces: fixed at outlets; elsewhere extrapolated with the last gradient, which
  // is exact for the linear pressure of uniform flow (porous bed, channel).
  const Mesh& m = *mesh_;
  ScalarField pb(m.nBoundaryFaces());
  for (int b = 0; b < m.nBoundaryFaces(); ++b) {
    const int c = m.boundaryCell(b);
    const auto& pc = patch_[m.boundaryPatch(b)];
    if (pc.type == BoundaryType::PressureOutlet)
      pb[b] = (pc.pressure - pRef_) - rho_ * g_.dot(m.boundaryCentre(b));
    else
      pb[b] = pRgh_[c] + gradPrgh_[c].dot(m.boundaryCentre(b) - m.cellCentre(c));
  }
  return pb;
}

void GasSolver::assembleMomentum(double dt) {
  const Mesh& m = *mesh_;
  const int nOwned = m.nOwnedCells();
  mom_ = std::make_unique<LduMatrix>(m);
  bU_.assign(nOwned, Vec3::Zero());
  for (auto& d : diagExtra_) d.assign(nOwned, 0.0);

  // d(a rho u)/dt + div(a rho u u) minus u times continuity: rho a_old V (u - u_old)/dt +
  // rho sum phi (u_f - u_P) + rho q V u_P, which keeps the discrete operator bounded.
  ScalarField implicitCoeff(nOwned);
  for (int c = 0; c < nOwned; ++c) {
    const double V = m.cellVolume(c);
    const double ddt = rho_ * alphaOld_[c] * V / dt;
    implicitCoeff[c] = ddt + beta_[c] * V + rho_ * injection_[c] * V;
    bU_[c] = ddt * Uold_[c] + betaUs_[c] * V + rho_ * injectionMomentum_[c] * V;
  }
  fvm::Sp(*mom_, implicitCoeff);

  ScalarField massFlux(phi_.size());
  for (std::size_t f = 0; f < phi_.size(); ++f) massFlux[f] = rho_ * phi_[f];
  fvm::convectionUpwind(*mom_, massFlux);

  const ScalarField alphaF = fvc::interpolate(m, alpha_);
  ScalarField gamma(alphaF.size());
  for (std::size_t f = 0; f < alphaF.size(); ++f) gamma[f] = mu_ * alphaF[f];
  fvm::laplacian(*mom_, gamma);

  // Explicit part of the stress, div(a mu (grad u)^T): zero for constant a and div u = 0, but not
  // in a bed with varying a. With it the non-orthogonal correction of the implicit part: the laplacian
  // takes (u_N - u_O) / delta, the derivative along d = x_N - x_O over its normal length, and the
  // normal derivative is that plus J (n - d / (d.n)). Between cut cells' centroids d leaves the normal by
  // O(1) (first order in the velocity without it); between whole cells d is along n and it is zero.
  // Summed over each cell's faces as fvc::surfaceSum would, without a face field.
  const auto gradU = fvc::grad(m, U_, boundaryVelocity());
  VectorField transposeSource(nOwned, Vec3::Zero());
  const std::vector<int>& nonOrthogonal = m.nonOrthogonalFaces();  // ascending
  std::size_t nextNonOrthogonal = 0;
  for (int f = 0; f < m.nInternalFaces(); ++f) {
    const int o = m.faceOwner(f), n = m.faceNeighbour(f), k = m.faceAxis(f);
    Vec3 t;
    if (nextNonOrthogonal < nonOrthogonal.size() && nonOrthogonal[nextNonOrthogonal] == f) {
      const Eigen::Matrix3d J = fvc::interpolate(m, gradU, f);
      t = gamma[f] * (J.transpose() * m.faceArea(f));
      // Added on its own: inside one expression with the product above, Eigen sums that product in
      // another order.
      t += gamma[f] * m.faceMagArea(f) * (J * m.nonOrthogonality(nextNonOrthogonal));
      ++nextNonOrthogonal;
    } else {
      // J^T times an area vector along axis k: row k of J times the area (the other rows meet zeros). Eigen
      // evaluates gamma (J^T A) as (gamma J^T) A, and so does this.
      const Vec3 Jk = fvc::interpolate<Vec3>(m, f, [&gradU, k](int c) { return gradU[c].row(k).transpose(); });
      t = (gamma[f] * Jk) * m.faceArea(f)[k];
    }
    if (o < nOwned) transposeSource[o] += t;
    if (n < nOwned) transposeSource[n] -= t;
  }
  for (int b = 0; b < m.nBoundaryFaces(); ++b) {
    const int c = m.boundaryCell(b);
    transposeSource[c] += mu_ * alpha_[c] * (gradU[c].transpose() * m.boundaryArea(b));
  }
  for (int c = 0; c < nOwned; ++c) bU_[c] += transposeSource[c];

  if (settings_.solver.convection == ConvectionScheme::LimitedLinearUpwind)
    addDeferredCorrection(gradU);
  addBoundaryMomentum();
}

void GasSolver::addDeferredCorrection(const std::vector<Eigen::Matrix3d>& gradU) {
  // Limited linear-upwind (van Leer limiter on the gradient ratio, Darwish & Moukalled 2003) as a
  // deferred correction to the implicit upwind flux: bounded (TVD) and second order where smooth.
  const Mesh& m = *mesh_;
  const int nOwned = m.nOwnedCells();
  for (int f = 0; f < m.nInternalFaces(); ++f) {
    const double F = rho_ * phi_[f];
    if (F == 0.0) continue;
    const int o = m.faceOwner(f), n = m.faceNeighbour(f);
    const int up = F > 0 ? o : n, down = F > 0 ? n : o;
    const Vec3 d = m.cellCentre(down) - m.cellCentre(up);
    Vec3 correction = Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
      const double jump = U_[down][k] - U_[up][k];
      if (jump == 0.0) continue;
      const double r = 2.0 * gradU[up].row(k).dot(d) / jump - 1.0;
      const double psi = (r + std::abs(r)) / (1.0 + std::abs(r));
      correction[k] = 0.5 * psi * jump;
    }
    if (o < nOwned) bU_[o] -= F * correction;
    if (n < nOwned) bU_[n] += F * correction;
  }
}

void GasSolver::addBoundaryMomentum() {
  const Mesh& m = *mesh_;
  const VectorField ub = boundaryVelocity();
  auto& diag = mom_->diag();
  for (int b = 0; b < m.nBoundaryFaces(); ++b) {
    const int c = m.boundaryCell(b);
    const auto& pc = patch_[m.boundaryPatch(b)];
    const double gD = mu_ * alpha_[c] * m.boundaryMagArea(b) / m.boundaryDelta(b);
    const double inflow = std::max(-rho_ * phiB_[b], 0.0);  // mass flow entering through the face
    switch (pc.type) {
      case BoundaryType::NoSlipWall: diag[c] += gD; break;
      case BoundaryType::FreeSlipWall: diagExtra_[dominantAxis(m.boundaryArea(b))][c] += gD; break;
      case BoundaryType::VelocityInlet:
        diag[c] += gD + inflow;
        bU_[c] += (gD + inflow) * ub[b];
        break;
      case BoundaryType::PressureOutlet:
        // Zero gradient for outflow; backflow enters normal to the face with the flux's speed.
        if (inflow > 0.0) {
          const Vec3 n = m.boundaryArea(b) / m.boundaryMagArea(b);
          diag[c] += inflow;
          bU_[c] += inflow * (phiB_[b] / (alpha_[c] * m.boundaryMagArea(b))) * n;
        }
        break;
    }
  }
}

void GasSolver::solveMomentum() {
  const Mesh& m = *mesh_;
  const int nOwned = m.nOwnedCells();
  for (int k = 0; k < 3; ++k) {
    ScalarField x(m.nLocalCells()), rhs(nOwned);
    for (int c = 0; c < m.nLocalCells(); ++c) x[c] = U_[c][k];
    for (int c = 0; c < nOwned; ++c)
      rhs[c] = bU_[c][k] - alpha_[c] * m.cellVolume(c) * gradPrgh_[c][k];
    const KrylovSolver solver(*mom_, settings_.solver.momentum, diagExtra_[k]);
    const SolveStats stats = solver.bicgstab(x, rhs, stoppingRule(settings_.solver.momentum));
    report_.momentumIterations += stats.iterations;
    report_.unconvergedSolves += stats.converged ? 0 : 1;
    for (int c = 0; c < m.nLocalCells(); ++c) U_[c][k] = x[c];
  }
}

}  // namespace parcelflow::cfd
