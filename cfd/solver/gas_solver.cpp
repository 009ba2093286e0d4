#include "cfd/solver/gas_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cfd/base/config_error.hpp"
#include "cfd/base/internal_error.hpp"
#include "cfd/mesh/mesh_builder.hpp"
#include "cfd/base/number_text.hpp"

namespace parcelflow::cfd {

namespace {
double rampFactor(double rampTime, double t) { return rampTime > 0.0 ? std::min(1.0, t / rampTime) : 1.0; }
}  // namespace

GasSolver::GasSolver(const GasSettings& settings, MPI_Comm comm)
    : GasSolver(settings,
                std::make_shared<const Mesh>(MeshBuilder::build(settings.mesh, settings.geometry, comm))) {}

GasSolver::GasSolver(const GasSettings& settings, std::shared_ptr<const Mesh> mesh)
    : settings_(settings),
      mesh_(std::move(mesh)),
      rho_(settings.gas.density),
      mu_(settings.gas.viscosity),
      g_(settings.gas.gravity),
      pPrecond_(settings.solver.pressure.preconditioner, settings.solver.pressure.preconditionerReuse) {
  const int nLocal = mesh_->nLocalCells();
  alpha_.assign(nLocal, 1.0);
  alphaOld_ = alpha_;
  beta_.assign(nLocal, 0.0);
  injection_.assign(nLocal, 0.0);
  betaUs_.assign(nLocal, Vec3::Zero());
  injectionMomentum_.assign(nLocal, Vec3::Zero());
  U_.assign(nLocal, Vec3::Zero());
  Uold_ = U_;
  pRgh_.assign(nLocal, 0.0);
  p_.assign(nLocal, 0.0);
  gradPrgh_.assign(nLocal, Vec3::Zero());
  gradP_.assign(nLocal, Vec3::Zero());
  phi_.assign(mesh_->nInternalFaces(), 0.0);
  phiB_.assign(mesh_->nBoundaryFaces(), 0.0);
  setupBoundaries();
  setupInletRegions();
  initialiseHydrostatic();
}

void GasSolver::setupBoundaries() {
  const Mesh& m = *mesh_;
  patch_.assign(m.patchNames().size(), PatchCondition{});
  bool haveOutlet = false;
  for (const auto& bc : settings_.boundaries) {
    const int id = m.patchId(bc.patch);
    if (id < 0) {
      std::string existing;
      for (std::size_t p = 0; p < m.patchNames().size(); ++p)
        if (m.patchGlobalFaces(static_cast<int>(p)) > 0)
          existing += (existing.empty() ? "" : ", ") + m.patchNames()[p];
      throw ConfigError("case.yaml: boundaries." + bc.patch +
                        ": the mesh has no patch of that name; its patches are: " + existing);
    }
    patch_[id] = {bc.type, bc.superficialVelocity, bc.pressure, true, bc.rampTime};
    if (bc.distributorPressureDrop > 0.0)
      patch_[id].resistance = bc.distributorPressureDrop / bc.superficialVelocity.norm();
    haveOutlet = haveOutlet || bc.type == BoundaryType::PressureOutlet;
  }
  for (std::size_t p = 0; p < patch_.size(); ++p)
    if (m.patchGlobalFaces(static_cast<int>(p)) > 0 && !patch_[p].defined)
      throw ConfigError("case.yaml: boundaries: patch '" + m.patchNames()[p] +
                        "' has no condition; give it type velocity_inlet, pressure_outlet or wall");
  if (!haveOutlet)
    throw ConfigError("case.yaml: boundaries: at least one patch must be a pressure_outlet "
                      "(it fixes the pressure level and lets the gas leave)");
  checkEveryRegionHasAnOutlet();
  int tangentialPlate = -1;  // a distributor patch whose velocity is not normal to one of its faces here
  for (int b = 0; b < m.nBoundaryFaces(); ++b) {
    const auto& pc = patch_[m.boundaryPatch(b)];
    if (pc.resistance > 0.0) {
      const Vec3 n = m.boundaryArea(b) / m.boundaryMagArea(b);
      if ((pc.superficialVelocity - pc.superficialVelocity.dot(n) * n).norm() > 1e-12 * pc.superficialVelocity.norm())
        tangentialPlate = std::max(tangentialPlate, m.boundaryPatch(b));
      // The start value; from then on the pressure correction sets these fluxes.
      phiB_[b] = rampFactor(pc.rampTime, 0.0) * pc.superficialVelocity.dot(m.boundaryArea(b));
    }
    if (pc.type == BoundaryType::FreeSlipWall) {
      const Vec3 n = m.boundaryArea(b).cwiseAbs() / m.boundaryMagArea(b);
      PARCELFLOW_ASSERT(n.maxCoeff() == 1.0, "free-slip walls need axis-aligned faces");
    }
  }
  // Only the ranks with faces of the patch can see it: agreed on by all, so that all stop alike.
  MPI_Allreduce(MPI_IN_PLACE, &tangentialPlate, 1, MPI_INT, MPI_MAX, m.comm());
  if (tangentialPlate >= 0)
    throw ConfigError("case.yaml: boundaries." + m.patchNames()[tangentialPlate] +
                      ".superficial_velocity: a distributor plate needs a velocity normal to its faces");
}

void GasSolver::checkEveryRegionHasAnOutlet() const {
  const Mesh& m = *mesh_;
  std::vector<int> reached(m.nFluidRegions(), 0);
  for (int b = 0; b < m.nBoundaryFaces(); ++b)
    if (patch_[m.boundaryPatch(b)].type == BoundaryType::PressureOutlet) reached[m.fluidRegion(m.boundaryCell(b))] = 1;
  MPI_Allreduce(MPI_IN_PLACE, reached.data(), static_cast<int>(reached.size()), MPI_INT, MPI_MAX, m.comm());
  long pockets = 0, pocketCells = 0;
  int first = -1;
  for (int r = 0; r < m.nFluidRegions(); ++r)
    if (!reached[r]) {
      ++pockets;
      pocketCells += m.fluidRegionCells(r);
      if (first < 0) first = r;
    }
  if (first < 0) return;
  const Vec3& x = m.fluidRegionPoint(first);
  throw ConfigError("case.yaml: geometry: " + std::to_string(m.fluidRegionCells(first)) + " fluid cell(s), the first at " +
                    formatNumbers("(%g, %g, %g)", x[0], x[1], x[2]) +
                    ", share no open face with the fluid that reaches a pressure_outlet (" +
                    std::to_string(pockets) + " such pocket(s), " + std::to_string(pocketCells) +
                    " cells; cells touching only along an edge or at a corner are apart): the gas pressure "
                    "there has no level. Fill the pocket in the geometry, join it through a face, or give "
                    "it an outlet");
}

void GasSolver::setupInletRegions() {
  const Mesh& m = *mesh_;
  for (std::size_t r = 0; r < settings_.inletRegions.size(); ++r) {
    const auto& region = settings_.inletRegions[r];
    double volume = 0.0;
    for (int c = 0; c < m.nOwnedCells(); ++c)
      if (region.region.isFluid(m.cellCentre(c))) volume += m.cellVolume(c);
    volume = m.sum(volume);
    if (volume <= 0.0)
      throw ConfigError("case.yaml: inlet_regions[" + std::to_string(r) + "].region (" +
                        region.name + "): contains no fluid cell centre");
    // The flow is spread uniformly over the region's volume, so it is injected exactly.
    InletRegionCells cells{{}, region.flowRate / volume, region.velocity, region.rampTime};
    for (int c = 0; c < m.nOwnedCells(); ++c)
      if (region.region.isFluid(m.cellCentre(c))) cells.cells.push_back(c);
    inletRegions_.push_back(std::move(cells));
  }
  applyInletRamps(0.0);
}

void GasSolver::applyInletRamps(double t) {
  const Mesh& m = *mesh_;
  for (auto& pc : patch_) pc.scale = rampFactor(pc.rampTime, t);
  for (int b = 0; b < m.nBoundaryFaces(); ++b) {
    const auto& pc = patch_[m.boundaryPatch(b)];
    if (pc.type == BoundaryType::VelocityInlet && pc.resistance == 0.0)
      phiB_[b] = pc.scale * pc.superficialVelocity.dot(m.boundaryArea(b));
  }
  std::fill(injection_.begin(), injection_.end(), 0.0);
  std::fill(injectionMomentum_.begin(), injectionMomentum_.end(), Vec3::Zero());
  for (const auto& region : inletRegions_) {
    const double q = rampFactor(region.rampTime, t) * region.q;
    for (int c : region.cells) {
      injection_[c] += q;
      injectionMomentum_[c] += q * region.velocity;
    }
  }
}

void GasSolver::initialiseHydrostatic() {
  // p_rgh = p - rho g.x is uniform at rest; start from the outlet value so gas at rest stays exactly
  // at rest (all outlet faces at one height give one value).
  const Mesh& m = *mesh_;
  double value = std::numeric_limits<double>::infinity();
  for (int b = 0; b < m.nBoundaryFaces(); ++b) {
    const auto& pc = patch_[m.boundaryPatch(b)];
    if (pc.type == BoundaryType::PressureOutlet)
      value = std::min(value, pc.pressure - rho_ * g_.dot(m.boundaryCentre(b)));
  }
  double global = 0.0;
  MPI_Allreduce(&value, &global, 1, MPI_DOUBLE, MPI_MIN, m.comm());
  pRef_ = global;
  pRgh_.assign(m.nLocalCells(), 0.0);
  gradPrgh_.assign(m.nLocalCells(), Vec3::Zero());
  for (int c = 0; c < m.nLocalCells(); ++c) {
    p_[c] = pRef_ + rho_ * g_.dot(m.cellCentre(c));
    gradP_[c] = rho_ * g_;
  }
}

template <class Field>
void GasSolver::copyOwned(const Field& in, Field& out, const char* what) const {
  const int nOwned = mesh_->nOwnedCells();
  if (static_cast<int>(in.size()) != nOwned && static_cast<int>(in.size()) != mesh_->nLocalCells())
    throw ConfigError(std::string("GasSolver: ") + what + " has " + std::to_string(in.size()) +
                      " entries; expected nOwnedCells or nLocalCells");
  std::copy(in.begin(), in.begin() + nOwned, out.begin());
  mesh_->exchange(out);
}

void GasSolver::setGasFraction(const ScalarField& alphaG) {
  copyOwned(alphaG, alpha_, "gas fraction");
  for (int c = 0; c < mesh_->nOwnedCells(); ++c)
    PARCELFLOW_ASSERT(alpha_[c] > 0.0 && alpha_[c] <= 1.0,
                          "gas fraction outside (0, 1]: the coupling floor must prevent this");
  // The first field given is the initial state; later ones are new time levels.
  if (!gasFractionGiven_) alphaOld_ = alpha_;
  gasFractionGiven_ = true;
}

void GasSolver::setDragCoefficient(const ScalarField& beta) {
  copyOwned(beta, beta_, "drag coefficient");
}

void GasSolver::setDragSource(const VectorField& betaUs) {
  copyOwned(betaUs, betaUs_, "drag source");
}

void GasSolver::setVelocity(const VectorField& u) {
  copyOwned(u, U_, "velocity");
  Uold_ = U_;
}

StepReport GasSolver::advance(double dt) {
  PARCELFLOW_ASSERT(dt > 0.0, "time step must be positive");
  report_ = StepReport{};
  applyInletRamps(time_ + dt);  // implicit Euler: the inlets at the new time level
  assembleMomentum(dt);
  solveMomentum();
  const int correctors = settings_.solver.pisoCorrectors;
  for (int corr = 0; corr < correctors; ++corr) correctPressure(dt, corr == 0, corr == correctors - 1);
  finishStep(dt);
  return report_;
}

GasSolver::State GasSolver::state() const {
  const int n = mesh_->nOwnedCells();
  State s;
  s.alpha.assign(alpha_.begin(), alpha_.begin() + n);
  s.pRgh.assign(pRgh_.begin(), pRgh_.begin() + n);
  s.gradPRgh.assign(gradPrgh_.begin(), gradPrgh_.begin() + n);
  s.velocity.assign(U_.begin(), U_.begin() + n);
  s.phi = phi_;
  s.phiBoundary = phiB_;
  s.time = time_;
  return s;
}

void GasSolver::restore(const State& s) {
  const Mesh& m = *mesh_;
  PARCELFLOW_ASSERT(static_cast<int>(s.alpha.size()) == m.nOwnedCells() && s.phi.size() == phi_.size() &&
                        s.phiBoundary.size() == phiB_.size(),
                    "restored gas state does not fit the mesh");
  copyOwned(s.alpha, alpha_, "gas fraction");
  copyOwned(s.pRgh, pRgh_, "pressure");
  copyOwned(s.velocity, U_, "velocity");
  copyOwned(s.gradPRgh, gradPrgh_, "pressure gradient");
  alphaOld_ = alpha_;
  Uold_ = U_;
  gasFractionGiven_ = true;
  phi_ = s.phi;
  phiB_ = s.phiBoundary;
  time_ = s.time;
  // As at the end of the step.
  for (int c = 0; c < m.nLocalCells(); ++c) {
    p_[c] = pRef_ + pRgh_[c] + rho_ * g_.dot(m.cellCentre(c));
    gradP_[c] = gradPrgh_[c] + rho_ * g_;
  }
  pPrecond_.rebuildNextStep();
}

double GasSolver::patchOutflow(const std::string& patch) const {
  const int id = mesh_->patchId(patch);
  if (id < 0) throw ConfigError("GasSolver::patchOutflow: no patch named '" + patch + "'");
  double local = 0.0;
  for (int b = 0; b < mesh_->nBoundaryFaces(); ++b)
    if (mesh_->boundaryPatch(b) == id) local += phiB_[b];
  return mesh_->sum(local);
}

double GasSolver::gasVolume() const {
  double local = 0.0;
  for (int c = 0; c < mesh_->nOwnedCells(); ++c) local += alpha_[c] * mesh_->cellVolume(c);
  return mesh_->sum(local);
}

}  // namespace parcelflow::cfd
