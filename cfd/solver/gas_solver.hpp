#pragma once
// The volume-averaged incompressible gas solver (see cfd/README.md for the equations and numerics).
//
// Interface for the coupling layer (all collective over the mesh communicator):
//   GasSolver gas(GasConfig(root).settings(), comm);
//   gas.setGasFraction(a_g);          // cell field, a_g = 1 - a_s at the new time level (the first
//                                     // call sets the initial state; a_g = 1 until then)
//   gas.setDragCoefficient(beta);     // cell field [kg/(m^3 s)], implicit part of B (u_s - u)
//   gas.setDragSource(betaUs);        // cell vector field beta * u_s [N/m^3], explicit part
//   StepReport r = gas.advance(dt);   // one implicit-Euler PISO step of fixed size dt
//   gas.velocity(), gas.pressure(), gas.pressureGradient()   // cell-centred u (interstitial), p, grad p
// Input fields may have nOwnedCells() or nLocalCells() entries; only owned entries are read and the
// ghosts are filled by a halo exchange. Output fields have nLocalCells() entries with valid ghosts.
// pressureGradient() is exactly the grad p used in the momentum equation (Gauss gradient of the
// pressure minus the hydrostatic part, plus rho g), so forces on particles and gas balance.
#include <memory>
#include <string>

#include "cfd/solver/gas_settings.hpp"
#include "cfd/linear/krylov_solver.hpp"
#include "cfd/linear/ldu_matrix.hpp"
#include "cfd/mesh/mesh.hpp"
#include "cfd/linear/reused_preconditioner.hpp"

namespace parcelflow::cfd {

struct StepReport {
  double cfl = 0.0;                 // max over cells of 0.5 dt sum|phi_f| / (a_g V)
  int momentumIterations = 0;       // BiCGStab iterations, summed over the 3 components
  int pressureIterations = 0;       // PCG iterations, summed over the PISO correctors
  int unconvergedSolves = 0;        // linear solves that stopped at max_iterations (never hidden)
  bool pressurePreconditionerBuilt = false;  // this step built it (else it reused the kept one)
  double continuityError = 0.0;     // sum |cell continuity residual| / the step's gas flow (flowScale())
  double boundaryOutflow = 0.0;     // net volumetric gas flow out through all patches [m^3/s]
  double injectedFlow = 0.0;        // inlet regions [m^3/s]
};

class GasSolver {
 public:
  GasSolver(const GasSettings& settings, MPI_Comm comm);
  // Builds on an existing mesh (must outlive the solver).
  GasSolver(const GasSettings& settings, std::shared_ptr<const Mesh> mesh);

  const Mesh& mesh() const { return *mesh_; }
  const GasSettings& settings() const { return settings_; }

  void setGasFraction(const ScalarField& alphaG);
  void setDragCoefficient(const ScalarField& beta);
  void setDragSource(const VectorField& betaUs);
  void setVelocity(const VectorField& u);  // initial condition (interstitial)

  StepReport advance(double dt);

  const ScalarField& gasFraction() const { return alpha_; }
  const VectorField& velocity() const { return U_; }
  const ScalarField& pressure() const { return p_; }
  const VectorField& pressureGradient() const { return gradP_; }
  double time() const { return time_; }
  const StepReport& lastReport() const { return report_; }

  // What the next step reads besides the settings (a checkpoint): gas fraction, p_rgh, its gradient (lagged:
  // the boundary values of p_rgh are extrapolated with the last one) and u of the owned cells, the face
  // fluxes of all local faces, and the time. The old time levels equal the current ones between steps, so
  // they are not stored twice.
  struct State {
    ScalarField alpha, pRgh;
    VectorField gradPRgh, velocity;
    ScalarField phi, phiBoundary;
    double time = 0.0;
  };
  State state() const;
  // Restores a state (ghosts exchanged at once; p and grad p recomputed as at the end of a step).
  void restore(const State& state);
  // The next step builds a new pressure preconditioner instead of reusing the kept one. A checkpoint calls
  // it, so the run that wrote it and a run restarted from it solve the same way.
  void rebuildPreconditionerNextStep() { pPrecond_.rebuildNextStep(); }

  // Net outward volumetric gas flow (a_g u . S summed) through a named patch, global [m^3/s].
  double patchOutflow(const std::string& patch) const;
  // Gas volume sum a_g V over the mesh [m^3].
  double gasVolume() const;

 private:
  struct PatchCondition {
    BoundaryType type = BoundaryType::NoSlipWall;
    Vec3 superficialVelocity = Vec3::Zero();
    double pressure = 0.0;
    bool defined = false;
    double rampTime = 0.0;
    double scale = 1.0;       // the ramp's factor at the current time level
    double resistance = 0.0;  // distributor plate: pressure drop / superficial velocity [Pa s/m]; 0 = none
  };
  // An inlet region's owned cells and its source per volume at full flow.
  struct InletRegionCells {
    std::vector<int> cells;
    double q = 0.0;
    Vec3 velocity = Vec3::Zero();
    double rampTime = 0.0;
  };

  void setupBoundaries();
  // Stops with a ConfigError when a face-connected fluid region has no pressure-outlet face.
  void checkEveryRegionHasAnOutlet() const;
  void setupInletRegions();
  // Inlet fluxes and sources at time t: each rises linearly from 0 over its ramp_time.
  void applyInletRamps(double t);
  void initialiseHydrostatic();
  // Owned entries of a scalar or vector field (owned- or local-size), then a halo exchange.
  template <class Field>
  void copyOwned(const Field& in, Field& out, const char* what) const;

  // gas_solver_momentum.cpp
  VectorField boundaryVelocity() const;
  ScalarField boundaryPressure() const;
  void assembleMomentum(double dt);
  void addBoundaryMomentum();
  void addDeferredCorrection(const std::vector<Eigen::Matrix3d>& gradU);
  void solveMomentum();
  // gas_solver_pressure.cpp
  void correctPressure(double dt, bool firstCorrector, bool lastCorrector);
  // The gas flow a step moves [m^3/s], what its continuity error is relative to: the largest of the flow
  // through the domain (sum |phi_b| over boundary faces + injected flow, of the current fluxes), the gas
  // the changing gas fraction displaces (sum V |alpha - alpha_old| / dt) and the continuity imbalance the
  // step's pressure solve starts from (stepImbalance_). A bed settling in a closed column has only the
  // second; a bubbling bed under its inflow mostly the first; a bed that starts to fall in a closed column
  // only the third (its parcels' drag drives gas that the pressure must stop, nothing passes or is
  // displaced yet).
  double flowScale(double dt) const;
  // Distributor inlets: adds the response to the plenum pressure P (solved with the matrix of this step) so
  // that the plates let in exactly their flow; returns P (p_rgh) and counts the extra solve's iterations.
  double addPlenumPressure(const ScalarField& plateCoeff, double inflow);
  void finishStep(double dt);

  GasSettings settings_;
  std::shared_ptr<const Mesh> mesh_;
  double rho_, mu_;
  Vec3 g_;
  std::vector<PatchCondition> patch_;
  std::vector<InletRegionCells> inletRegions_;
  ScalarField alpha_, alphaOld_, beta_, injection_;
  // |continuity residual|_1 of the fluxes with the step's predicted velocity and the previous pressure
  // [m^3/s]: the first PISO corrector's initial pressure residual, set there each step.
  double stepImbalance_ = 0.0;
  VectorField betaUs_, injectionMomentum_, U_, Uold_;
  // p = pRef_ + pRgh_ + rho g.x: the solved part pRgh_ stays small next to an absolute outlet pressure
  // (1e5 Pa), so tight solver tolerances still resolve the cell-to-cell differences that drive u.
  double pRef_ = 0.0;
  ScalarField pRgh_, p_;
  VectorField gradPrgh_, gradP_;
  ScalarField phi_, phiB_;  // internal (owner -> neighbour) and boundary (outward) volume fluxes
  std::unique_ptr<LduMatrix> mom_;
  // The pressure matrix is the same for all PISO correctors of a step; its preconditioner is kept
  // over several steps.
  std::unique_ptr<LduMatrix> pEqn_;
  std::unique_ptr<KrylovSolver> pSolver_;
  ReusedPreconditioner pPrecond_;
  VectorField bU_;                       // momentum source without the pressure gradient
  std::array<ScalarField, 3> diagExtra_;  // per-component diagonal (free-slip normal components)
  StepReport report_;
  double time_ = 0.0;
  bool gasFractionGiven_ = false;
};

}  // namespace parcelflow::cfd
