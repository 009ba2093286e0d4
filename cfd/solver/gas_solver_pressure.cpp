// GasSolver: PISO pressure correction with a Rhie-Chow face flux. The momentum diagonal A includes
// the drag coefficient beta V, so in dense beds the pressure coefficients D = a V / A and
// Dt = a V / (A - H1) are drag-dominated on faces and cells alike: no odd-even decoupling. Gravity
// enters through p_rgh = p - rho g.x - p_ref (constant gas density), so the hydrostatic balance is
// exact on faces.
#include <algorithm>
#include <cmath>

#include "cfd/fv/fvc.hpp"
#include "cfd/base/internal_error.hpp"
#include "cfd/solver/gas_solver.hpp"
#include "cfd/linear/krylov_solver.hpp"

namespace parcelflow::cfd {


void GasSolver::correctPressure(double dt, bool firstCorrector, bool lastCorrector) {
  const Mesh& m = *mesh_;
  const int nOwned = m.nOwnedCells(), nLocal = m.nLocalCells();
  const auto& diag = mom_->diag();

  // HbyA = (b - sum_N a_N u_N) / A per component: A_k includes the component's own boundary
  // diagonal (free-slip walls fix only the normal component), so nothing is lagged. Faces are
  // axis-aligned, so a face's flux only needs the component D_k of its normal axis k.
  // SIMPLEC-consistent coupling: the pressure equation uses Dt = a V / (A - H1), H1 = -sum_N a_N,
  // i.e. only the time, drag, injection and boundary parts of the diagonal. Plain a V / A makes
  // PISO diverge when diffusion dominates the time term (large dt, fine walls, Stokes flow).
  VectorField H(nLocal, Vec3::Zero()), HbyA(nLocal, Vec3::Zero());
  VectorField D(nLocal, Vec3::Zero()), Dt(nLocal, Vec3::Zero());
  ScalarField rowOffDiag(nOwned, 0.0);
  for (int c = 0; c < nOwned; ++c) H[c] = bU_[c];
  for (int f = 0; f < m.nInternalFaces(); ++f) {
    const int o = m.faceOwner(f), n = m.faceNeighbour(f);
    if (o < nOwned) {
      H[o] -= mom_->upper()[f] * U_[n];
      rowOffDiag[o] += mom_->upper()[f];
    }
    if (n < nOwned) {
      H[n] -= mom_->lower()[f] * U_[o];
      rowOffDiag[n] += mom_->lower()[f];
    }
  }
  for (int c = 0; c < nOwned; ++c) {
    const double aV = alpha_[c] * m.cellVolume(c);
    for (int k = 0; k < 3; ++k) {
      const double A = diag[c] + diagExtra_[k][c];
      const double excess = A + rowOffDiag[c];
      PARCELFLOW_ASSERT(excess > 0.0, "momentum matrix is not diagonally dominant");
      HbyA[c][k] = H[c][k] / A;
      D[c][k] = aV / A;
      Dt[c][k] = aV / excess;
    }
  }
  m.exchange(HbyA);
  m.exchange(D);
  m.exchange(Dt);

  // Face values interpolated where they are used (the component of the face's axis only for D and Dt).
  const ScalarField alphaF = fvc::interpolate(m, alpha_);
  const auto faceComponent = [&m](int f, const VectorField& cells, int k) {
    return fvc::interpolate<double>(m, f, [&cells, k](int c) { return cells[c][k]; });
  };
  ScalarField phiHbyA(m.nInternalFaces()), coeff(m.nInternalFaces());
  if (firstCorrector) pEqn_ = std::make_unique<LduMatrix>(m);
  for (int f = 0; f < m.nInternalFaces(); ++f) {
    const int k = m.faceAxis(f);
    const double DFk = faceComponent(f, D, k), DtFk = faceComponent(f, Dt, k);
    const double snGrad = (pRgh_[m.faceNeighbour(f)] - pRgh_[m.faceOwner(f)]) / m.faceDelta(f);
    phiHbyA[f] =
        alphaF[f] * (fvc::interpolate(m, HbyA, f).dot(m.faceArea(f)) + (DtFk - DFk) * snGrad * m.faceMagArea(f));
    coeff[f] = alphaF[f] * DtFk * m.faceMagArea(f) / m.faceDelta(f);
    if (firstCorrector) pEqn_->addSymmetric(f, coeff[f]);
  }
  // Non-orthogonal correction: (p_N - p_O) / delta is the derivative along d = x_N - x_O, and the normal
  // derivative is that plus grad p . (n - d / (d.n)). Between cut cells' centroids d leaves the normal
  // (the pressure gradient along the face enters the flux there); the correction takes the gradient of
  // the previous corrector, explicitly, so the matrix stays symmetric. In the flux it appears through
  // both pressure terms, (Dt - D) with the old and -Dt with the new pressure: -D in sum, the momentum
  // equation's own -D grad p at convergence. Between whole cells it is exactly zero: only the mesh's
  // non-orthogonal faces take it.
  const std::vector<int>& nonOrthogonal = m.nonOrthogonalFaces();
  for (std::size_t listed = 0; listed < nonOrthogonal.size(); ++listed) {
    const int f = nonOrthogonal[listed];
    const double DFk = faceComponent(f, D, m.faceAxis(f));
    phiHbyA[f] -= alphaF[f] * DFk * m.faceMagArea(f) *
                  fvc::interpolate(m, gradPrgh_, f).dot(m.nonOrthogonality(listed));
  }
  ScalarField phiHbyAB(m.nBoundaryFaces(), 0.0), coeffB(m.nBoundaryFaces(), 0.0);
  ScalarField pB = boundaryPressure();
  // Every rank knows all patches, so all take the distributor branches together (they are collective).
  const bool plates =
      std::any_of(patch_.begin(), patch_.end(), [](const PatchCondition& pc) { return pc.resistance > 0.0; });
  ScalarField rhs(nOwned, 0.0), plateCoeff(plates ? nOwned : 0, 0.0);  // distributor faces' A/R per cell
  double plateInflow = 0.0;
  for (int b = 0; b < m.nBoundaryFaces(); ++b) {
    const int c = m.boundaryCell(b);
    const auto& pc = patch_[m.boundaryPatch(b)];
    const auto type = pc.type;
    if (type == BoundaryType::VelocityInlet && pc.resistance > 0.0) {
      // Distributor plate: superficial velocity (P - p) / R into the cell, P the plenum pressure: like an
      // outlet at the pressure P, which addPlenumPressure finds.
      coeffB[b] = m.boundaryMagArea(b) / pc.resistance;
      if (firstCorrector) pEqn_->diag()[c] += coeffB[b];
      plateCoeff[c] += coeffB[b];
      plateInflow -= pc.scale * pc.superficialVelocity.dot(m.boundaryArea(b));
    } else if (type == BoundaryType::VelocityInlet) {
      phiHbyAB[b] = phiB_[b];
    }
    if (type == BoundaryType::PressureOutlet) {
      const int k = dominantAxis(m.boundaryArea(b));
      const double snGrad = (pB[b] - pRgh_[c]) / m.boundaryDelta(b);
      phiHbyAB[b] = alpha_[c] * (HbyA[c].dot(m.boundaryArea(b)) +
                                 (Dt[c][k] - D[c][k]) * snGrad * m.boundaryMagArea(b));
      coeffB[b] = alpha_[c] * Dt[c][k] * m.boundaryMagArea(b) / m.boundaryDelta(b);
      if (firstCorrector) pEqn_->diag()[c] += coeffB[b];
      rhs[c] += coeffB[b] * pB[b];
    }
  }
  const VectorField gradOld = gradPrgh_;
  // Continuity: V (a - a_old)/dt + sum phi = q V, with phi = phiHbyA - coeff dp.
  const ScalarField divHbyA = fvc::surfaceSum(m, phiHbyA, phiHbyAB);
  for (int c = 0; c < nOwned; ++c)
    rhs[c] -= divHbyA[c] + m.cellVolume(c) * ((alpha_[c] - alphaOld_[c]) / dt - injection_[c]);

  if (firstCorrector) {
    pSolver_ = std::make_unique<KrylovSolver>(*pEqn_, settings_.solver.pressure, pPrecond_.forStep(*pEqn_));
    report_.pressurePreconditionerBuilt = pPrecond_.builtThisStep();
    stepImbalance_ = pSolver_->residualOneNorm(pRgh_, rhs);
  }
  // The residual of this equation is the continuity residual the corrected fluxes keep, cell by cell (phi
  // = phiHbyA - coeff dp): its 1-norm over the step's gas flow is the step's continuity error, so the
  // normalized criterion bounds that error by its tolerance. The through-flow part is taken from the fluxes
  // before this solve (the previous corrector's or step's, with the inlets at the new time level); the
  // reported error divides by the one after it, which differs by this solve's change of the outlet fluxes.
  const SolveStats stats =
      pSolver_->pcg(pRgh_, rhs, stoppingRule(settings_.solver.pressure, lastCorrector, flowScale(dt)));
  pPrecond_.recordIterations(stats.iterations);
  report_.pressureIterations += stats.iterations;
  report_.unconvergedSolves += stats.converged ? 0 : 1;
  if (plates) {
    const double plenum = addPlenumPressure(plateCoeff, m.sum(plateInflow));
    for (int b = 0; b < m.nBoundaryFaces(); ++b)
      if (patch_[m.boundaryPatch(b)].resistance > 0.0) pB[b] = plenum;
  }

  for (int f = 0; f < m.nInternalFaces(); ++f)
    phi_[f] = phiHbyA[f] - coeff[f] * (pRgh_[m.faceNeighbour(f)] - pRgh_[m.faceOwner(f)]);
  for (int b = 0; b < m.nBoundaryFaces(); ++b)
    phiB_[b] = phiHbyAB[b] - coeffB[b] * (pB[b] - pRgh_[m.boundaryCell(b)]);

  gradPrgh_ = fvc::grad(m, pRgh_, boundaryPressure());
  for (int c = 0; c < nOwned; ++c)
    U_[c] = HbyA[c] + (Dt[c] - D[c]).cwiseProduct(gradOld[c]) - Dt[c].cwiseProduct(gradPrgh_[c]);
  m.exchange(U_);
}

double GasSolver::addPlenumPressure(const ScalarField& plateCoeff, double inflow) {
  // The pressure is linear in P: p = p1 + P p2, p1 solved with P = 0 (in pRgh_), p2 the response to P = 1
  // (right-hand side plateCoeff). The plates let in sum c (P - p) = inflow, so
  // P = (inflow + sum c p1) / sum c (1 - p2): the flow is exact whatever the plate pressures do.
  const Mesh& m = *mesh_;
  const int nOwned = m.nOwnedCells();
  // Always strict: its residual enters the continuity error multiplied by the plenum pressure P.
  ScalarField response(m.nLocalCells(), 0.0);
  const SolveStats stats = pSolver_->pcg(response, plateCoeff, strictRule(settings_.solver.pressure));
  pPrecond_.recordIterations(stats.iterations);
  report_.pressureIterations += stats.iterations;
  report_.unconvergedSolves += stats.converged ? 0 : 1;
  double num = 0.0, den = 0.0;
  for (int c = 0; c < nOwned; ++c) {
    num += plateCoeff[c] * pRgh_[c];
    den += plateCoeff[c] * (1.0 - response[c]);
  }
  const double plenum = (inflow + m.sum(num)) / m.sum(den);
  for (int c = 0; c < m.nLocalCells(); ++c) pRgh_[c] += plenum * response[c];
  return plenum;
}

double GasSolver::flowScale(double dt) const {
  const Mesh& m = *mesh_;
  double through = 0.0, displaced = 0.0;
  for (int b = 0; b < m.nBoundaryFaces(); ++b) through += std::abs(phiB_[b]);
  for (int c = 0; c < m.nOwnedCells(); ++c) {
    through += injection_[c] * m.cellVolume(c);
    displaced += m.cellVolume(c) * std::abs(alpha_[c] - alphaOld_[c]) / dt;
  }
  return std::max({m.sum(through), m.sum(displaced), stepImbalance_});
}

void GasSolver::finishStep(double dt) {
  const Mesh& m = *mesh_;
  const int nOwned = m.nOwnedCells();
  ScalarField absFlux(m.nInternalFaces()), absFluxB(m.nBoundaryFaces());
  for (int f = 0; f < m.nInternalFaces(); ++f) absFlux[f] = std::abs(phi_[f]);
  for (int b = 0; b < m.nBoundaryFaces(); ++b) absFluxB[b] = std::abs(phiB_[b]);
  // Outward sums: the internal faces' sign flips for the neighbour, so sum |phi| per cell directly.
  ScalarField sumAbs(nOwned, 0.0);
  for (int f = 0; f < m.nInternalFaces(); ++f) {
    if (m.faceOwner(f) < nOwned) sumAbs[m.faceOwner(f)] += absFlux[f];
    if (m.faceNeighbour(f) < nOwned) sumAbs[m.faceNeighbour(f)] += absFlux[f];
  }
  for (int b = 0; b < m.nBoundaryFaces(); ++b) sumAbs[m.boundaryCell(b)] += absFluxB[b];
  const ScalarField divPhi = fvc::surfaceSum(m, phi_, phiB_);
  double cfl = 0.0, continuity = 0.0, outflow = 0.0, injected = 0.0;
  for (int c = 0; c < nOwned; ++c) {
    const double V = m.cellVolume(c);
    cfl = std::max(cfl, 0.5 * dt * sumAbs[c] / (alpha_[c] * V));
    continuity += std::abs(V * (alpha_[c] - alphaOld_[c]) / dt + divPhi[c] - injection_[c] * V);
    injected += injection_[c] * V;
  }
  for (int b = 0; b < m.nBoundaryFaces(); ++b) outflow += phiB_[b];
  report_.cfl = m.max(cfl);
  report_.boundaryOutflow = m.sum(outflow);
  report_.injectedFlow = m.sum(injected);
  report_.continuityError = m.sum(continuity) / std::max(flowScale(dt), 1e-300);

  for (int c = 0; c < m.nLocalCells(); ++c) {
    p_[c] = pRef_ + pRgh_[c] + rho_ * g_.dot(m.cellCentre(c));
    gradP_[c] = gradPrgh_[c] + rho_ * g_;
  }
  alphaOld_ = alpha_;
  Uold_ = U_;
  time_ += dt;
}

}  // namespace parcelflow::cfd
