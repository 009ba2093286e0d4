#include "cfd/solver/gas_config.hpp"

#include <filesystem>
#include <utility>
#include <vector>

#include "cfd/base/config_error.hpp"
#include "cfd/io/yaml_duplicate_keys.hpp"
#include "cfd/io/yaml_section.hpp"

namespace parcelflow::cfd {

namespace {
constexpr double kMaxBackgroundCells = 1e8;
}  // namespace

const std::vector<std::string>& GasConfig::ownedTopLevelKeys() {
  static const std::vector<std::string> keys{"mesh",       "geometry",      "gas",
                                             "boundaries", "inlet_regions", "solver"};
  return keys;
}

GasConfig GasConfig::fromFile(const std::string& path) {
  checkNoDuplicateKeys(path);
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw ConfigError("cannot read " + path + ": " + e.what());
  }
  return GasConfig(root, std::filesystem::path(path).parent_path().string());
}

GasConfig::GasConfig(const YAML::Node& root, const std::string& caseFolder)
    : caseFolder_(caseFolder.empty() ? "." : caseFolder) {
  const YamlSection top(root, "");
  top.allowAnyKeys();  // the case's reader checks the top-level keys: it knows the coupling layer's too
  settings_.mesh = readMesh(top.map("mesh"));
  settings_.geometry = readGeometry(top);
  settings_.gas = readGas(top.map("gas"));
  settings_.boundaries = readBoundaries(top.map("boundaries"));
  settings_.inletRegions = readInletRegions(top);
  settings_.solver = top.has("solver") ? readSolver(top.map("solver")) : SolverSettings{};
}

MeshSettings GasConfig::readMesh(const YamlSection& s) const {
  s.allowOnly({"origin", "lengths", "cells", "ghost_layers", "partition_weights", "walls", "small_cell_fraction"});
  MeshSettings m;
  // Up to 10 km, far beyond any apparatus: at 1e300 m the first pressure solve did no iteration and the
  // run went on until the blow-up guard stopped it (the coordinates lose all precision).
  m.origin = s.vec3("origin", Vec3::Zero(), Range::closed(-1e4, 1e4));
  m.lengths = s.vec3("lengths", std::nullopt, Range::leftOpen(0.0, 1e4));
  m.cells = s.int3("cells", 1, 100000);
  // Every rank holds about 24 bytes per background cell of index maps (mesh builder, mesh, the coupling's
  // owner map) and global cell ids are int: refuse before allocating (cfd/README.md, mesh).
  const double total = 1.0 * m.cells[0] * m.cells[1] * m.cells[2];
  if (total > kMaxBackgroundCells)
    s.fail("cells", "has " + std::to_string(static_cast<long long>(total)) + " background cells; allowed are at "
                    "most 1e8 in total (each rank holds about 24 bytes per background cell: 2.4 GB at 1e8)");
  m.ghostLayers = s.integer("ghost_layers", 2, 1, 5);
  m.walls = s.word("walls", "staircase", {"staircase", "cut_cells"}) == "cut_cells" ? WallRepresentation::CutCells
                                                                                   : WallRepresentation::Staircase;
  // Below 1e-3 a cell's fluid centroid can lie a round-off from its faces (cfd/README.md, "Cut cells in the
  // solver"); above one half a cell that is mostly fluid would be merged.
  m.smallCellFraction = s.number("small_cell_fraction", kDefaultSmallCellFraction, Range::closed(1e-3, 0.5));
  if (s.has("small_cell_fraction") && m.walls != WallRepresentation::CutCells)
    s.fail("small_cell_fraction", "applies only with walls: cut_cells (staircase meshes have no cut cells)");
  if (s.has("partition_weights")) {
    for (const auto& item : s.listOfMaps("partition_weights")) {
      item.allowOnly({"region", "weight"});
      PartitionWeight w;
      w.region = Primitive::fromYaml(item.map("region"), caseFolder_);
      w.weight = item.integer("weight", std::nullopt, 1, 1000);
      m.partitionWeights.push_back(w);
    }
  }
  return m;
}

Geometry GasConfig::readGeometry(const YamlSection& top) const {
  if (!top.has("geometry")) return Geometry();
  return readShapeList(top, "geometry");
}

Geometry GasConfig::readShapeList(const YamlSection& parent, const std::string& key) const {
  std::vector<Geometry::Item> items;
  for (const auto& item : parent.listOfMaps(key)) {
    item.allowOnly({"op", "shape", "patch"});
    const std::string op = item.word("op", "union", {"union", "cut"});
    const std::string patch = item.text("patch", "");
    if (op == "union" && !patch.empty())
      item.fail("patch", "is only allowed with op: cut (it names the walls of the cut-out)");
    items.push_back({op == "union" ? Geometry::Op::Union : Geometry::Op::Cut,
                     Primitive::fromYaml(item.map("shape"), caseFolder_), patch});
  }
  return Geometry(items);
}

GasProperties GasConfig::readGas(const YamlSection& s) {
  s.allowOnly({"density", "viscosity", "gravity"});
  GasProperties g;
  // Any gas is denser than 1e-3 kg/m3 (air at 1 mbar); at 1e-300 the momentum matrix's time and convection
  // terms vanish against round-off of its viscous part (cfd/README.md).
  g.density = s.number("density", std::nullopt, Range::closed(1e-3, 1e4));
  g.viscosity = s.number("viscosity", std::nullopt, Range::leftOpen(0, 1e3));
  g.gravity = s.vec3("gravity", Vec3(0, 0, -9.81), Range::closed(-1e3, 1e3));
  return g;
}

std::vector<BoundarySettings> GasConfig::readBoundaries(const YamlSection& s) {
  // Patch names are free here: the mesh decides which exist (checked when the solver is built).
  s.allowAnyKeys();
  std::vector<BoundarySettings> out;
  for (const auto& name : s.keys()) {
    const YamlSection b = s.map(name);
    // Every boundary key first (a misspelt `type` is named as such), then those of its type.
    b.allowOnly({"type", "superficial_velocity", "ramp_time", "distributor_pressure_drop", "pressure", "slip"});
    BoundarySettings bc;
    bc.patch = name;
    const std::string type = b.word("type", std::nullopt, {"velocity_inlet", "pressure_outlet", "wall"});
    if (type == "velocity_inlet") {
      b.allowOnly({"type", "superficial_velocity", "ramp_time", "distributor_pressure_drop"});
      bc.type = BoundaryType::VelocityInlet;
      bc.superficialVelocity = b.vec3("superficial_velocity", std::nullopt, Range::closed(-1e3, 1e3));
      bc.rampTime = b.number("ramp_time", 0.0, Range::closed(0.0, 1e6));
      bc.distributorPressureDrop = b.number("distributor_pressure_drop", 0.0, Range::closed(0.0, 1e9));
      if (bc.distributorPressureDrop > 0.0 && bc.superficialVelocity.norm() == 0.0)
        b.fail("distributor_pressure_drop", "needs a non-zero superficial_velocity (the plate's resistance is "
                                            "its pressure drop over that velocity)");
    } else if (type == "pressure_outlet") {
      b.allowOnly({"type", "pressure"});
      bc.type = BoundaryType::PressureOutlet;
      bc.pressure = b.number("pressure", 0.0, Range::closed(-1e9, 1e9));
    } else {
      b.allowOnly({"type", "slip"});
      bc.type = b.word("slip", "no_slip", {"no_slip", "free_slip"}) == "no_slip"
                    ? BoundaryType::NoSlipWall
                    : BoundaryType::FreeSlipWall;
    }
    out.push_back(bc);
  }
  return out;
}

std::vector<InletRegionSettings> GasConfig::readInletRegions(const YamlSection& top) const {
  std::vector<InletRegionSettings> out;
  if (!top.has("inlet_regions")) return out;
  for (const auto& item : top.listOfMaps("inlet_regions")) {
    item.allowOnly({"name", "region", "flow_rate", "velocity", "ramp_time"});
    InletRegionSettings r;
    r.name = item.text("name", std::nullopt);
    r.region = readShapeList(item, "region");
    if (r.region.items().empty()) item.fail("region", "must list at least one shape");
    r.flowRate = item.number("flow_rate", std::nullopt, Range::positive());
    r.velocity = item.vec3("velocity", Vec3::Zero(), Range::closed(-1e3, 1e3));
    r.rampTime = item.number("ramp_time", 0.0, Range::closed(0.0, 1e6));
    out.push_back(r);
  }
  return out;
}

LinearSolverSettings GasConfig::readLinearSolver(const YamlSection& s, LinearSolverSettings fallback,
                                                 bool pressure) {
  LinearSolverSettings l = fallback;
  std::vector<std::string> keys{"criterion", "tolerance", "absolute_tolerance", "rel_tol", "max_iterations",
                                "preconditioner"};
  if (pressure) keys.insert(keys.end(), {"final_rel_tol", "preconditioner_reuse"});
  s.allowOnly(keys);
  if (pressure) l.preconditionerReuse = s.integer("preconditioner_reuse", fallback.preconditionerReuse, 1, 1000);
  readStoppingCriterion(s, l, pressure);
  l.maxIterations = s.integer("max_iterations", fallback.maxIterations, 1, 100000);
  static const std::vector<std::pair<std::string, PreconditionerType>> names = {
      {"jacobi", PreconditionerType::Jacobi},
      {"block_ic", PreconditionerType::BlockIncompleteCholesky},
      {"block_cholesky", PreconditionerType::BlockCholesky},
      {"boomeramg", PreconditionerType::BoomerAmg}};
  std::string current;
  std::vector<std::string> allowed;
  for (const auto& [name, type] : names) {
    allowed.push_back(name);
    if (type == fallback.preconditioner) current = name;
  }
  const std::string p = s.word("preconditioner", current, allowed);
  for (const auto& [name, type] : names)
    if (name == p) l.preconditioner = type;
  return l;
}

void GasConfig::readStoppingCriterion(const YamlSection& s, LinearSolverSettings& l, bool pressure) {
  const bool strict = s.word("criterion", l.criterion == StoppingCriterion::Strict ? "strict" : "normalized",
                             {"strict", "normalized"}) == "strict";
  const std::vector<std::string> otherKeys =
      strict ? std::vector<std::string>{"rel_tol", "final_rel_tol"} : std::vector<std::string>{"absolute_tolerance"};
  for (const auto& key : otherKeys)
    if (s.has(key))
      s.fail(key, std::string("is only allowed with criterion: ") + (strict ? "normalized" : "strict") +
                      " (criterion is " + (strict ? "strict" : "normalized") + ")");
  if (strict) {
    l.criterion = StoppingCriterion::Strict;
    l.relTolerance = s.number("tolerance", l.relTolerance, Range::closed(1e-16, 0.1));
    l.absTolerance = s.number("absolute_tolerance", l.absTolerance, Range::nonNegative());
    return;
  }
  l.criterion = StoppingCriterion::Normalized;
  l.tolerance = s.number("tolerance", l.tolerance, Range::closed(1e-16, 0.1));
  // Below 1: a fraction of the initial residual (1 would stop before the first iteration).
  const Range fraction{0.0, 1.0, false, true};
  l.relTol = s.number("rel_tol", l.relTol, fraction);
  if (pressure) l.finalRelTol = s.number("final_rel_tol", l.finalRelTol, fraction);
}

SolverSettings GasConfig::readSolver(const YamlSection& s) {
  s.allowOnly({"piso_correctors", "convection", "pressure", "momentum"});
  SolverSettings out;
  out.pisoCorrectors = s.integer("piso_correctors", out.pisoCorrectors, 1, 10);
  const std::string conv =
      s.word("convection", "limited_linear_upwind", {"upwind", "limited_linear_upwind"});
  out.convection =
      conv == "upwind" ? ConvectionScheme::Upwind : ConvectionScheme::LimitedLinearUpwind;
  if (s.has("pressure")) out.pressure = readLinearSolver(s.map("pressure"), out.pressure, true);
  if (s.has("momentum")) {
    out.momentum = readLinearSolver(s.map("momentum"), out.momentum, false);
    if (out.momentum.preconditioner != PreconditionerType::Jacobi)
      s.map("momentum").fail("preconditioner",
                             "must be jacobi (the momentum matrix is not symmetric)");
  }
  return out;
}

}  // namespace parcelflow::cfd
