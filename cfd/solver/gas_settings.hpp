#pragma once
// Plain settings of the gas solver, as read from case.yaml by GasConfig (see cfd/README.md for every
// key, its unit and default). Tests and the coupling layer may also fill them directly.
#include <string>
#include <vector>

#include "cfd/base/types.hpp"
#include "cfd/geometry/geometry.hpp"
#include "cfd/linear/linear_solver_settings.hpp"
#include "cfd/mesh/mesh_settings.hpp"

namespace parcelflow::cfd {

struct GasProperties {
  double density = 1.2;       // kg/m^3
  double viscosity = 1.8e-5;  // dynamic, Pa s
  Vec3 gravity{0.0, 0.0, -9.81};
};

enum class BoundaryType { VelocityInlet, PressureOutlet, NoSlipWall, FreeSlipWall };

struct BoundarySettings {
  std::string patch;
  BoundaryType type = BoundaryType::NoSlipWall;
  Vec3 superficialVelocity = Vec3::Zero();  // velocity_inlet
  double pressure = 0.0;                    // pressure_outlet, total pressure [Pa]
  double rampTime = 0.0;                    // velocity_inlet: rises linearly from 0 over this time [s]
  // velocity_inlet through a distributor plate: its pressure drop at the full superficial velocity [Pa]; 0 =
  // the same velocity on every face.
  double distributorPressureDrop = 0.0;
};

struct InletRegionSettings {
  std::string name;
  Geometry region;               // unions and cut-outs of primitives (a ring = cylinder cut cylinder)
  double flowRate = 0.0;          // m^3/s of gas injected, spread over the region's cells by volume
  Vec3 velocity = Vec3::Zero();   // velocity of the injected gas (carries momentum rho*q*velocity)
  double rampTime = 0.0;          // the flow rises linearly from 0 over this time [s]
};

enum class ConvectionScheme { Upwind, LimitedLinearUpwind };

struct SolverSettings {
  int pisoCorrectors = 2;
  ConvectionScheme convection = ConvectionScheme::LimitedLinearUpwind;
  // Normalized by default, with the values of OpenFOAM's PISO tutorials (p: 1e-6, relTol 0.05, pFinal relTol
  // 0; U: 1e-5, relTol 0.1); the proof that it changes no physics is in cfd/README.md ("The coupled proof").
  LinearSolverSettings pressure{1e-8, 1e-30, 1000, PreconditionerType::BoomerAmg, 20,
                                StoppingCriterion::Normalized, 1e-6, 0.05, 0.0};
  LinearSolverSettings momentum{1e-8, 1e-30, 1000, PreconditionerType::Jacobi, 1,
                                StoppingCriterion::Normalized, 1e-5, 0.1, 0.0};
};

struct GasSettings {
  MeshSettings mesh;
  Geometry geometry;
  GasProperties gas;
  std::vector<BoundarySettings> boundaries;
  std::vector<InletRegionSettings> inletRegions;
  SolverSettings solver;
};

}  // namespace parcelflow::cfd
