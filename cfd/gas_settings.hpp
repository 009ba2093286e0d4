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

// How the gas sees the walls of `geometry:`: whole background cells selected by their centre, or cut
// cells (fluid volume, open face areas and a wall face per cut cell; cfd/README.md, "Cut cells in the
// solver").
enum class WallRepresentation { Staircase, CutCells };

// MFiX removes cut cells under 1 % of the volume; here they are merged into a neighbour (cell_groups.hpp),
// so no volume is lost. case.yaml: mesh.small_cell_fraction.
constexpr double kDefaultSmallCellFraction = 0.01;

struct MeshSettings {
  Vec3 origin = Vec3::Zero();
  Vec3 lengths = Vec3::Ones();
  std::array<int, 3> cells{1, 1, 1};
  int ghostLayers = 2;
  std::vector<PartitionWeight> partitionWeights;  // later entries override earlier ones
  WallRepresentation walls = WallRepresentation::Staircase;
  double smallCellFraction = kDefaultSmallCellFraction;  // cut cells below this share of a cell are merged
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

// When a linear solve stops (cfd/README.md, "Stopping the linear solves").
//   Strict: |r|_2 <= max(relTolerance |b|_2, absTolerance) on every solve.
//   Normalized (OpenFOAM's PISO practice): |r|_1 / n <= max(tolerance, relTol * initial |r|_1 / n), with
//   relTol = finalRelTol for the last PISO corrector's pressure solve. The normalization n is the step's gas
//   flow for the pressure (GasSolver::flowScale; the residual is the step's continuity error) and OpenFOAM's
//   sum|A x0 - A xbar| + sum|b - A xbar| for the momentum components.
enum class StoppingCriterion { Strict, Normalized };

struct LinearSolverSettings {
  double relTolerance = 1e-8;   // strict: on the residual 2-norm relative to the right-hand side's
  double absTolerance = 1e-30;  // strict: on the residual 2-norm
  int maxIterations = 1000;
  PreconditionerType preconditioner = PreconditionerType::BlockIncompleteCholesky;
  int preconditionerReuse = 1;  // gas steps one preconditioner serves at most (reused_preconditioner.hpp)
  StoppingCriterion criterion = StoppingCriterion::Strict;
  double tolerance = 1e-6;    // normalized: on the normalized residual
  double relTol = 0.0;        // normalized: fraction of the initial residual (0 = off)
  double finalRelTol = 0.0;   // normalized, pressure: relTol of the last PISO corrector
};

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
