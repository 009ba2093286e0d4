#pragma once
// Plain settings of the gas solver, as read from case.yaml by GasConfig (see cfd/README.md for every
// key, its unit and default). Tests and the coupling layer may also fill them directly.
#include <array>
#include <string>
#include <vector>

#include "geometry.hpp"
#include "types.hpp"

namespace parcelflow::cfd {

struct PartitionWeight {
  Primitive region;
  int weight = 1;  // METIS vertex weight of cells whose centre is inside `region`
};

struct MeshSettings {
  Vec3 origin = Vec3::Zero();
  Vec3 lengths = Vec3::Ones();
  std::array<int, 3> cells{1, 1, 1};
  int ghostLayers = 2;
  std::vector<PartitionWeight> partitionWeights;  // later entries override earlier ones
};

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
enum class PreconditionerType { Jacobi, BlockIncompleteCholesky, BlockCholesky, BoomerAmg };

struct LinearSolverSettings {
  double relTolerance = 1e-8;   // on the residual norm relative to the right-hand side norm
  double absTolerance = 1e-30;  // on the residual 2-norm
  int maxIterations = 1000;
  PreconditionerType preconditioner = PreconditionerType::BlockIncompleteCholesky;
  int preconditionerReuse = 1;  // gas steps one preconditioner serves at most (reused_preconditioner.hpp)
};

struct SolverSettings {
  int pisoCorrectors = 2;
  ConvectionScheme convection = ConvectionScheme::LimitedLinearUpwind;
  LinearSolverSettings pressure{1e-8, 1e-30, 1000, PreconditionerType::BoomerAmg, 20};
  LinearSolverSettings momentum{1e-8, 1e-30, 1000, PreconditionerType::Jacobi};
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
