#include "cfd/solver/gas_energy.hpp"

#include <algorithm>

#include "cfd/base/internal_error.hpp"
#include "cfd/linear/krylov_solver.hpp"
#include "cfd/linear/ldu_matrix.hpp"

namespace parcelflow::cfd {

GasEnergy::GasEnergy(std::shared_ptr<const Mesh> mesh, double density, const std::vector<BoundarySettings>& boundaries,
                     GasThermalSettings settings)
    : mesh_(std::move(mesh)), rho_(density), settings_(std::move(settings)) {
  const Mesh& m = *mesh_;
  PARCELFLOW_ASSERT(rho_ > 0.0 && settings_.heatCapacity > 0.0 && settings_.conductivity >= 0.0 &&
                        settings_.initialTemperature > 0.0,
                    "gas energy: the case reader checks density, heat capacity, conductivity and temperature");
  patch_.assign(m.patchNames().size(), Patch{});
  for (const BoundarySettings& b : boundaries) {
    const int id = m.patchId(b.patch);
    if (id < 0) continue;  // a patch no face of the mesh has
    Patch& p = patch_[id];
    switch (b.type) {
      case BoundaryType::VelocityInlet: p.condition = Condition::Inflow; break;
      case BoundaryType::PressureOutlet:
        p.condition = Condition::Outflow;
        p.temperature = settings_.initialTemperature;
        break;
      case BoundaryType::NoSlipWall:
      case BoundaryType::FreeSlipWall: p.condition = Condition::Adiabatic; break;
    }
  }
  std::vector<bool> given(patch_.size(), false);
  for (const PatchTemperature& t : settings_.patches) {
    const int id = m.patchId(t.patch);
    PARCELFLOW_ASSERT(id >= 0 && t.temperature > 0.0, "gas energy: the case reader checks the patch temperatures");
    Patch& p = patch_[id];
    p.temperature = t.temperature;
    if (p.condition == Condition::Adiabatic) p.condition = Condition::FixedTemperature;
    given[id] = true;
  }
  for (std::size_t id = 0; id < patch_.size(); ++id)
    PARCELFLOW_ASSERT(patch_[id].condition != Condition::Inflow || given[id],
                      "gas energy: velocity inlet '" + m.patchNames()[id] + "' has no temperature");
  T_.assign(m.nLocalCells(), settings_.initialTemperature);
  alphaOld_.assign(m.nOwnedCells(), 1.0);
}

void GasEnergy::setGasFraction(const ScalarField& alpha) {
  const int nOwned = mesh_->nOwnedCells();
  PARCELFLOW_ASSERT(static_cast<int>(alpha.size()) >= nOwned, "gas energy: a gas fraction field of the wrong size");
  alphaOld_.assign(alpha.begin(), alpha.begin() + nOwned);
}

void GasEnergy::setTemperature(const ScalarField& T) {
  const int nOwned = mesh_->nOwnedCells();
  PARCELFLOW_ASSERT(static_cast<int>(T.size()) >= nOwned, "gas energy: a temperature field of the wrong size");
  std::copy(T.begin(), T.begin() + nOwned, T_.begin());
  mesh_->exchange(T_);
}

double GasEnergy::heatContent() const {
  const Mesh& m = *mesh_;
  const double rc = rho_ * settings_.heatCapacity;
  double local = 0.0;
  for (int c = 0; c < m.nOwnedCells(); ++c)
    local += rc * alphaOld_[c] * m.cellVolume(c) * T_[c];
  return m.sum(local);
}

EnergyStepReport GasEnergy::advance(double dt, const ScalarField& alpha, const ScalarField& phi,
                                    const ScalarField& phiBoundary, const ScalarField& exchangeCoeff,
                                    const ScalarField& exchangeSource) {
  const Mesh& m = *mesh_;
  const int nOwned = m.nOwnedCells();
  PARCELFLOW_ASSERT(static_cast<int>(alpha.size()) >= nOwned && static_cast<int>(phi.size()) == m.nInternalFaces() &&
                        static_cast<int>(phiBoundary.size()) == m.nBoundaryFaces() &&
                        static_cast<int>(exchangeCoeff.size()) >= nOwned &&
                        static_cast<int>(exchangeSource.size()) >= nOwned,
                    "gas energy: input fields of the wrong size");
  const double rc = rho_ * settings_.heatCapacity, k = settings_.conductivity;

  LduMatrix A(m);
  ScalarField b(nOwned, 0.0);
  for (int c = 0; c < nOwned; ++c) {
    const double V = m.cellVolume(c);
    A.diag()[c] += rc * alpha[c] * V / dt + exchangeCoeff[c];
    b[c] += rc * alphaOld_[c] * V / dt * T_[c] + exchangeSource[c];
  }
  // Internal faces: conservative upwind convection (F T_upwind leaves the owner and enters the neighbour)
  // and diffusion with the face's gas fraction.
  ScalarField alphaLocal(m.nLocalCells());
  std::copy(alpha.begin(), alpha.begin() + nOwned, alphaLocal.begin());
  m.exchange(alphaLocal);
  for (int f = 0; f < m.nInternalFaces(); ++f) {
    const int o = m.faceOwner(f), n = m.faceNeighbour(f);
    const double F = rc * phi[f];
    if (F >= 0.0) {
      if (o < nOwned) A.diag()[o] += F;
      if (n < nOwned) A.lower()[f] -= F;
    } else {
      if (o < nOwned) A.upper()[f] += F;
      if (n < nOwned) A.diag()[n] -= F;
    }
    const double w = m.faceWeight(f);
    const double alphaFace = w * alphaLocal[o] + (1.0 - w) * alphaLocal[n];
    A.addSymmetric(f, alphaFace * k * m.faceMagArea(f) / m.faceDelta(f));
  }
  // Boundary faces: what a face carries in or out, and the fixed-temperature walls.
  for (int f = 0; f < m.nBoundaryFaces(); ++f) {
    const int c = m.boundaryCell(f);
    const Patch& p = patch_[m.boundaryPatch(f)];
    const double F = rc * phiBoundary[f];
    switch (p.condition) {
      case Condition::Inflow:
      case Condition::Outflow:
        if (F >= 0.0)
          A.diag()[c] += F;
        else
          b[c] -= F * p.temperature;
        break;
      case Condition::FixedTemperature: {
        const double g = alpha[c] * k * m.boundaryMagArea(f) / m.boundaryDelta(f);
        A.diag()[c] += g;
        b[c] += g * p.temperature;
        break;
      }
      case Condition::Adiabatic: break;
    }
  }

  // BoomerAMG (the default) also keeps BiCGStab from breaking down on convection-dominated rows, where
  // upwind carries the residual downstream, orthogonal to the shadow residual (seen with Jacobi).
  const KrylovSolver solver(A, settings_.solver);
  const SolveStats stats = solver.bicgstab(T_, b, strictRule(settings_.solver));
  EnergyStepReport report;
  report.iterations = stats.iterations;
  report.converged = stats.converged;

  // The heat flows at the new temperature, as the equation balanced them.
  double convection = 0.0, wall = 0.0, exchange = 0.0;
  for (int f = 0; f < m.nBoundaryFaces(); ++f) {
    const int c = m.boundaryCell(f);
    const Patch& p = patch_[m.boundaryPatch(f)];
    const double F = rc * phiBoundary[f];
    if (p.condition == Condition::Inflow || p.condition == Condition::Outflow)
      convection -= F * (F >= 0.0 ? T_[c] : p.temperature);
    else if (p.condition == Condition::FixedTemperature)
      wall += alpha[c] * k * m.boundaryMagArea(f) / m.boundaryDelta(f) * (p.temperature - T_[c]);
  }
  for (int c = 0; c < nOwned; ++c) exchange += exchangeSource[c] - exchangeCoeff[c] * T_[c];
  report.boundaryConvection = m.sum(convection);
  report.wallConduction = m.sum(wall);
  report.exchange = m.sum(exchange);
  alphaOld_.assign(alpha.begin(), alpha.begin() + nOwned);
  return report;
}

}  // namespace parcelflow::cfd
