#pragma once
// The gas temperature: a scalar carried by the gas flow, with constant gas properties.
//
//   d(a rho c T)/dt + div(rho c phi T) = div(a k grad T) + sum over parcels of H (T_p - T)
//
// rho, c, k constant (the gas density does not follow T: valid while temperature differences stay small
// next to the absolute temperature, a few tens of kelvin in air; beyond that a low-Mach density from the
// ideal-gas law would be needed). phi = a u . S are the gas solver's face fluxes of the step, so the
// temperature moves with the same flow as the mass. Implicit Euler; upwind convection in conservative
// form (every face flux leaves one cell and enters the other), the exchange implicit (fvm::Sp style:
// the coefficient on the diagonal, the parcels' part on the right side), so sum a rho c V T changes by
// exactly what crosses the boundaries and what the parcels exchange, to the linear solve's tolerance.
// Boundaries by the gas patch type: velocity inlets bring gas at their temperature; pressure outlets
// let it leave (gas flowing back in comes at the outlet's temperature); walls are adiabatic or held at a
// fixed temperature.
#include <memory>
#include <string>
#include <vector>

#include "cfd/solver/gas_settings.hpp"
#include "cfd/mesh/mesh.hpp"
#include "cfd/base/types.hpp"

namespace parcelflow::cfd {

// A patch's temperature [K]: of the gas a velocity inlet brings, of the gas flowing back in at a pressure
// outlet, of a wall held at it (a wall not listed is adiabatic).
struct PatchTemperature {
  std::string patch;
  double temperature = 0.0;
};

struct GasThermalSettings {
  double heatCapacity = 1005.0;     // c [J/(kg K)]
  double conductivity = 0.026;      // k [W/(m K)]
  double initialTemperature = 293.15;
  std::vector<PatchTemperature> patches;  // every velocity inlet needs one; outlets default to the initial T
  LinearSolverSettings solver{1e-12, 1e-300, 1000, PreconditionerType::BoomerAmg, 1, StoppingCriterion::Strict,
                              1e-6, 0.0, 0.0};
};

// Heat flows of one step [W], positive into the gas, global.
struct EnergyStepReport {
  double boundaryConvection = 0.0;  // carried in (inlets, backflow) minus carried out through the patches
  double wallConduction = 0.0;      // through fixed-temperature walls
  double exchange = 0.0;            // from the parcels: sum H (T_p - T) at the new temperature
  int iterations = 0;  // BiCGStab iterations
  bool converged = true;
};

class GasEnergy {
 public:
  // `boundaries`: the gas solver's patches (their types decide the conditions); the mesh must outlive this.
  GasEnergy(std::shared_ptr<const Mesh> mesh, double density, const std::vector<BoundarySettings>& boundaries,
            GasThermalSettings settings);

  // One step of dt with the step's gas fraction a (new level) and face fluxes phi (internal, owner ->
  // neighbour) and phiBoundary (outward), as the gas solver left them; exchangeCoeff (sum H) [W/K] and
  // exchangeSource (sum H T_p) [W] per owned cell.
  EnergyStepReport advance(double dt, const ScalarField& alpha, const ScalarField& phi,
                           const ScalarField& phiBoundary, const ScalarField& exchangeCoeff,
                           const ScalarField& exchangeSource);

  // The gas fraction before the first step (owned entries read; 1 until given).
  void setGasFraction(const ScalarField& alpha);
  const ScalarField& temperature() const { return T_; }  // local cells, ghosts valid
  void setTemperature(const ScalarField& T);             // owned entries read; a checkpoint's or an initial field
  // sum a rho c V T over the mesh [J] with the gas fraction of the last step (or the one set before it)
  double heatContent() const;

 private:
  enum class Condition { Inflow, Outflow, Adiabatic, FixedTemperature };
  struct Patch {
    Condition condition = Condition::Adiabatic;
    double temperature = 0.0;
  };

  std::shared_ptr<const Mesh> mesh_;
  double rho_;
  GasThermalSettings settings_;
  std::vector<Patch> patch_;
  ScalarField T_, alphaOld_;
};

}  // namespace parcelflow::cfd
