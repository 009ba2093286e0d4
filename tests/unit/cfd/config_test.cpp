// GasConfig: a complete gas section parses; unknown keys (with the closest allowed name), wrong types and
// out-of-range values throw ConfigError naming the key path, the value and what is allowed.
#include <gtest/gtest.h>
#include <mpi.h>

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "cfd/base/config_error.hpp"
#include "cfd/solver/gas_config.hpp"
#include "cfd/solver/gas_solver.hpp"
#include "cfd/base/internal_error.hpp"
#include "cfd/io/yaml_duplicate_keys.hpp"
#include "cfd/io/yaml_section.hpp"

using namespace parcelflow::cfd;

namespace {
const char* kValid = R"(
mesh:
  origin: [0, 0, 0]
  lengths: [0.2, 0.2, 1.0]
  cells: [4, 4, 20]
  ghost_layers: 3
  partition_weights:
    - region: {box: {min: [0, 0, 0], max: [0.2, 0.2, 0.5]}}
      weight: 4
geometry:
  - shape: {cylinder: {center: [0.1, 0.1], radius: 0.1, zmin: 0, zmax: 0.8}}
  - shape: {cylinder: {center: [0.1, 0.1], radius: 0.04, zmin: 0.8, zmax: 1.0}}
  - op: cut
    shape: {box: {min: [0.05, 0.05, 0.3], max: [0.15, 0.15, 0.36]}}
    patch: baffle
gas:
  density: 1.2
  viscosity: 1.8e-5
  gravity: [0, 0, -9.81]
boundaries:
  zmin: {type: velocity_inlet, superficial_velocity: [0, 0, 0.1]}
  zmax: {type: pressure_outlet, pressure: 1.0e5}
  walls: {type: wall, slip: no_slip}
  xmin: {type: wall}
  xmax: {type: wall}
  ymin: {type: wall}
  ymax: {type: wall}
  baffle: {type: wall, slip: free_slip}
inlet_regions:
  - name: sparger
    region:
      - shape: {cylinder: {center: [0.1, 0.1], radius: 0.08, zmin: 0.05, zmax: 0.1}}
      - op: cut
        shape: {cylinder: {center: [0.1, 0.1], radius: 0.05, zmin: 0.0, zmax: 0.2}}
    flow_rate: 1.0e-3
    velocity: [0, 0, -1]
solver:
  piso_correctors: 3
  convection: upwind
  pressure: {tolerance: 1.0e-10, max_iterations: 500, preconditioner: block_cholesky}
  momentum: {tolerance: 1.0e-9}
coupling: {anything: the coupling layer checks this}
)";

// Parses kValid with one line replaced (or added) and returns the ConfigError message ("" if none).
std::string errorOf(const std::string& yaml) {
  try {
    GasConfig config(YAML::Load(yaml));
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

std::string replaced(const std::string& from, const std::string& to) {
  std::string text = kValid;
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return text.replace(pos, from.size(), to);
}

void expectError(const std::string& message, const std::vector<std::string>& parts) {
  ASSERT_FALSE(message.empty()) << "no ConfigError thrown";
  for (const auto& part : parts) EXPECT_NE(message.find(part), std::string::npos) << message;
}
}  // namespace

TEST(GasConfig, ValidFileParses) {
  const GasConfig config(YAML::Load(kValid));
  const auto& s = config.settings();
  EXPECT_EQ(s.mesh.cells[2], 20);
  EXPECT_EQ(s.mesh.ghostLayers, 3);
  EXPECT_EQ(s.mesh.walls, WallRepresentation::Staircase);  // the default
  EXPECT_EQ(s.mesh.smallCellFraction, kDefaultSmallCellFraction);
  const GasConfig cut(YAML::Load(replaced("  ghost_layers: 3", "  ghost_layers: 3\n  walls: cut_cells\n  small_cell_fraction: 0.05")));
  EXPECT_EQ(cut.settings().mesh.smallCellFraction, 0.05);
  EXPECT_EQ(s.mesh.partitionWeights.size(), 1u);
  EXPECT_EQ(s.geometry.items().size(), 3u);
  EXPECT_DOUBLE_EQ(s.gas.viscosity, 1.8e-5);
  EXPECT_EQ(s.boundaries.size(), 8u);
  EXPECT_EQ(s.inletRegions.size(), 1u);
  EXPECT_EQ(s.inletRegions[0].rampTime, 0.0);  // full flow from the start unless ramp_time is given
  EXPECT_TRUE(s.inletRegions[0].region.isFluid(Vec3(0.1 + 0.06, 0.1, 0.07)));
  EXPECT_FALSE(s.inletRegions[0].region.isFluid(Vec3(0.1, 0.1, 0.07)));
  EXPECT_EQ(s.solver.pisoCorrectors, 3);
  EXPECT_EQ(s.solver.convection, ConvectionScheme::Upwind);
  EXPECT_EQ(s.solver.pressure.preconditioner, PreconditionerType::BlockCholesky);
  // No criterion given: the default, normalized, whose tolerance the key sets.
  EXPECT_EQ(s.solver.pressure.criterion, StoppingCriterion::Normalized);
  EXPECT_EQ(s.solver.pressure.tolerance, 1e-10);
  EXPECT_EQ(s.solver.momentum.criterion, StoppingCriterion::Normalized);
  EXPECT_EQ(s.solver.momentum.tolerance, 1e-9);
  // The geometry: column, exit tube, baffle cut out.
  EXPECT_TRUE(s.geometry.isFluid(Vec3(0.1, 0.1, 0.9)));
  EXPECT_FALSE(s.geometry.isFluid(Vec3(0.01, 0.01, 0.9)));
  EXPECT_FALSE(s.geometry.isFluid(Vec3(0.1, 0.1, 0.32)));
  EXPECT_EQ(s.geometry.wallPatchAt(Vec3(0.1, 0.1, 0.32)), "baffle");
}

TEST(GasConfig, UnknownKeysAreNamed) {
  expectError(errorOf(replaced("  viscosity: 1.8e-5", "  viscosty: 1.8e-5")),
              {"unknown key gas.viscosty", "viscosity"});
  expectError(errorOf(replaced("  ghost_layers: 3", "  ghost_layer: 3")),
              {"mesh.ghost_layer", "ghost_layers"});
  expectError(errorOf(replaced("  convection: upwind", "  convection: upwind\n  relax: 0.7")),
              {"solver.relax"});
  expectError(errorOf(replaced("{type: wall, slip: no_slip}", "{type: wall, slipp: no_slip}")),
              {"boundaries.walls.slipp"});
}

// A misspelt key is named as the unknown key it is, with its value and the closest allowed name, also when
// the key it stands for is required (it used to be reported as `type` missing).
TEST(GasConfig, MisspeltKeysAreNamedWithTheClosestAllowedName) {
  const std::string requiredType = errorOf(replaced("xmin: {type: wall}", "xmin: {typ: wall}"));
  expectError(requiredType, {"case.yaml: unknown key boundaries.xmin.typ (value wall) is not allowed here; did you "
                             "mean type? allowed here: type, superficial_velocity, ramp_time, "
                             "distributor_pressure_drop, pressure, slip"});
  EXPECT_EQ(requiredType.find("required"), std::string::npos) << requiredType;
  expectError(errorOf(replaced("{type: wall, slip: no_slip}", "{type: wall, slpi: no_slip}")),
              {"unknown key boundaries.walls.slpi (value no_slip)", "did you mean slip?"});
  expectError(errorOf(replaced("  density: 1.2", "  densty: 1.2")),
              {"unknown key gas.densty (value 1.2)", "did you mean density?", "allowed here: density, viscosity"});
  expectError(errorOf(replaced("{cylinder: {center: [0.1, 0.1], radius: 0.04,", "{cylindre: {center: [0.1, 0.1], "
                                                                                 "radius: 0.04,")),
              {"unknown key geometry[1].shape.cylindre", "did you mean cylinder?", "allowed here: box, cylinder"});
  // Every unknown key of the map at once; no guess where no allowed name is near.
  const std::string two = errorOf(replaced("xmin: {type: wall}", "xmin: {tpye: wall, colour: red}"));
  expectError(two, {"unknown keys boundaries.xmin.tpye (value wall; did you mean type?), boundaries.xmin.colour "
                    "(value red) are not allowed here; allowed here: type,"});
  EXPECT_EQ(two.find("did you mean", two.find("colour")), std::string::npos) << two;
  // A key that belongs to another boundary type names the keys of this one.
  expectError(errorOf(replaced("xmin: {type: wall}", "xmin: {type: wall, pressure: 0}")),
              {"unknown key boundaries.xmin.pressure (value 0) is not allowed here; allowed here: type, slip"});
}

// Reading a value of a section whose keys were not checked first is a bug: the misspelt-key message depends on it.
TEST(YamlSection, ReadingBeforeTheKeysAreCheckedIsAnInternalError) {
  const YamlSection section(YAML::Load("{densty: 1.2}"), "gas");
  EXPECT_THROW(section.number("density", 1.0, Range::any()), InternalError);
  section.allowOnly({"densty"});
  EXPECT_DOUBLE_EQ(section.number("densty", std::nullopt, Range::any()), 1.2);
}

TEST(GasConfig, WrongTypesAreNamed) {
  expectError(errorOf(replaced("  density: 1.2", "  density: heavy")),
              {"gas.density", "heavy", "a number in [0.001, 10000]"});
  expectError(errorOf(replaced("  cells: [4, 4, 20]", "  cells: [4, 4]")),
              {"mesh.cells", "a list of 3 integers"});
  expectError(errorOf(replaced("  gravity: [0, 0, -9.81]", "  gravity: down")),
              {"gas.gravity", "list of 3 numbers"});
  expectError(errorOf(replaced("{box: {min: [0, 0, 0]", "{sphere: {min: [0, 0, 0]")),
              {"partition_weights[0].region.sphere", "box, cylinder"});
}

TEST(GasConfig, OutOfRangeValuesAreNamed) {
  expectError(errorOf(replaced("  viscosity: 1.8e-5", "  viscosity: -1")),
              {"gas.viscosity = -1", "must be a number in (0, 1000]"});
  expectError(errorOf(replaced("  ghost_layers: 3", "  ghost_layers: 0")),
              {"mesh.ghost_layers = 0", "[1, 5]"});
  expectError(errorOf(replaced("  ghost_layers: 3", "  ghost_layers: 3\n  walls: cut")),
              {"mesh.walls = cut", "staircase, cut_cells"});
  expectError(errorOf(replaced("  ghost_layers: 3", "  ghost_layers: 3\n  walls: cut_cells\n  small_cell_fraction: 0.6")),
              {"mesh.small_cell_fraction = 0.6", "[0.001, 0.5]"});
  expectError(errorOf(replaced("  ghost_layers: 3", "  ghost_layers: 3\n  small_cell_fraction: 0.05")),
              {"mesh.small_cell_fraction", "only with walls: cut_cells"});
  expectError(errorOf(replaced("  convection: upwind", "  convection: quick")),
              {"solver.convection = quick", "upwind, limited_linear_upwind"});
  expectError(errorOf(replaced("type: velocity_inlet,", "type: inlet,")),
              {"boundaries.zmin.type = inlet", "velocity_inlet, pressure_outlet, wall"});
  expectError(errorOf(replaced("radius: 0.04,", "radius: -0.04,")), {"geometry[1].shape.cylinder.radius"});
  expectError(errorOf(replaced("    flow_rate: 1.0e-3", "    flow_rate: 0")),
              {"inlet_regions[0].flow_rate = 0", "> 0"});
  expectError(errorOf(replaced("    flow_rate: 1.0e-3", "    flow_rate: 1.0e-3\n    ramp_time: -1")),
              {"inlet_regions[0].ramp_time = -1"});
  expectError(errorOf(replaced("superficial_velocity: [0, 0, 0.1]}", "superficial_velocity: [0, 0, 0.1], ramp_time: -0.5}")),
              {"boundaries.zmin.ramp_time = -0.5"});
  expectError(errorOf(replaced("superficial_velocity: [0, 0, 0.1]}", "superficial_velocity: [0, 0, 0.1], distributor_pressure_drop: -5}")),
              {"boundaries.zmin.distributor_pressure_drop = -5"});
  expectError(errorOf(replaced("superficial_velocity: [0, 0, 0.1]}", "superficial_velocity: [0, 0, 0], distributor_pressure_drop: 100}")),
              {"boundaries.zmin.distributor_pressure_drop", "non-zero superficial_velocity"});
  expectError(errorOf(replaced("momentum: {tolerance: 1.0e-9}", "momentum: {preconditioner: block_ic}")),
              {"solver.momentum.preconditioner", "jacobi"});
  expectError(errorOf(replaced("min: [0, 0, 0], max: [0.2, 0.2, 0.5]", "min: [0, 0, 0], max: [0.2, 0, 0.5]")),
              {"max", "larger than min"});
}

// solver.pressure / solver.momentum: criterion normalized (the default: tolerance on the normalized residual,
// rel_tol, final_rel_tol) or strict (|r|_2 <= tolerance |b|_2), each tolerance key only with its criterion.
TEST(GasConfig, StoppingCriterionKeys) {
  const std::string pressure = "pressure: {tolerance: 1.0e-10, max_iterations: 500, preconditioner: block_cholesky}";
  const std::string momentum = "momentum: {tolerance: 1.0e-9}";
  const auto settings = [&](const std::string& p, const std::string& u) {
    return GasConfig(YAML::Load(replaced(pressure, p).replace(replaced(pressure, p).find(momentum), momentum.size(), u)))
        .settings()
        .solver;
  };
  const SolverSettings strict = settings("pressure: {criterion: strict}", "momentum: {criterion: strict}");
  const SolverSettings defaults;
  EXPECT_EQ(strict.pressure.criterion, StoppingCriterion::Strict);
  EXPECT_EQ(strict.pressure.relTolerance, defaults.pressure.relTolerance);
  EXPECT_EQ(strict.pressure.absTolerance, defaults.pressure.absTolerance);
  EXPECT_EQ(strict.momentum.relTolerance, defaults.momentum.relTolerance);
  const SolverSettings normalized =
      settings("pressure: {criterion: normalized, tolerance: 1.0e-7, rel_tol: 0.01, final_rel_tol: 0.001}",
               "momentum: {criterion: normalized}");
  EXPECT_EQ(normalized.pressure.criterion, StoppingCriterion::Normalized);
  EXPECT_EQ(normalized.pressure.tolerance, 1e-7);
  EXPECT_EQ(normalized.pressure.relTol, 0.01);
  EXPECT_EQ(normalized.pressure.finalRelTol, 0.001);
  EXPECT_EQ(normalized.pressure.relTolerance, defaults.pressure.relTolerance);  // strict's, unchanged
  EXPECT_EQ(normalized.momentum.criterion, StoppingCriterion::Normalized);
  EXPECT_EQ(normalized.momentum.tolerance, defaults.momentum.tolerance);
  EXPECT_EQ(normalized.momentum.relTol, defaults.momentum.relTol);

  expectError(errorOf(replaced(pressure, "pressure: {criterion: loose}")),
              {"solver.pressure.criterion = loose", "strict, normalized"});
  expectError(errorOf(replaced(pressure, "pressure: {criterion: strict, rel_tol: 0.05}")),
              {"solver.pressure.rel_tol", "only allowed with criterion: normalized"});
  expectError(errorOf(replaced(pressure, "pressure: {criterion: strict, final_rel_tol: 0}")),
              {"solver.pressure.final_rel_tol", "only allowed with criterion: normalized"});
  expectError(errorOf(replaced(pressure, "pressure: {absolute_tolerance: 1.0e-20}")),
              {"solver.pressure.absolute_tolerance", "only allowed with criterion: strict"});
  expectError(errorOf(replaced(pressure, "pressure: {criterion: normalized, rel_tol: 1}")),
              {"solver.pressure.rel_tol = 1", "[0, 1)"});
  expectError(errorOf(replaced(pressure, "pressure: {criterion: normalized, final_rel_tol: -0.1}")),
              {"solver.pressure.final_rel_tol = -0.1", "[0, 1)"});
  expectError(errorOf(replaced(pressure, "pressure: {criterion: normalized, tolerance: 0.5}")),
              {"solver.pressure.tolerance = 0.5", "[1e-16, 0.1]"});
  expectError(errorOf(replaced(momentum, "momentum: {criterion: normalized, final_rel_tol: 0}")),
              {"unknown key solver.momentum.final_rel_tol"});
}

TEST(GasConfig, RangesTheSolverCannotHonourAreRefused) {
  expectError(errorOf(replaced("  density: 1.2", "  density: 1.0e-300")),
              {"gas.density = 1.0e-300", "[0.001, 10000]"});
  // Refused before the mesh is allocated (1e15 cells).
  expectError(errorOf(replaced("  cells: [4, 4, 20]", "  cells: [100000, 100000, 100000]")),
              {"mesh.cells", "1000000000000000 background cells", "at most 1e8"});
}

// A key given twice in one map is named with both lines (yaml-cpp's node API keeps the first silently).
TEST(GasConfig, DuplicatedKeysAreNamedWithBothLines) {
  char path[] = "/tmp/pf_config_test_XXXXXX";
  const int fd = mkstemp(path);
  ASSERT_GE(fd, 0);
  close(fd);
  const auto errorOfFile = [&](const std::string& text) {
    std::ofstream(path) << text;
    try {
      checkNoDuplicateKeys(path);
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  expectError(errorOfFile("a: 1\nb:\n  c: 2\n  d: [1, {e: 1, f: 2}]\n  c: 3\n"),
              {"b.c is given twice", "lines 3 and 5"});
  expectError(errorOfFile("a: 1\nlist:\n  - {x: 1}\n  - {x: 2, x: 3}\n"), {"list[1].x", "lines 4 and 4"});
  expectError(errorOfFile("a: 1\nb: 2\na: 3\n"), {"a is given twice", "lines 1 and 3"});
  EXPECT_EQ(errorOfFile("a: {x: 1}\nb: {x: 1}\nc: [{x: 1}, {x: 2}]\n"), "");
  std::remove(path);
}

TEST(GasConfig, PatchesAreCheckedAgainstTheMesh) {
  const std::string noBaffle = replaced("  baffle: {type: wall, slip: free_slip}\n", "  ghost: {type: wall}\n");
  try {
    GasSolver gas(GasConfig(YAML::Load(noBaffle)).settings(), MPI_COMM_WORLD);
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("boundaries.ghost"), std::string::npos) << e.what();
  }
  const std::string missing = replaced("  baffle: {type: wall, slip: free_slip}\n", "");
  try {
    GasSolver gas(GasConfig(YAML::Load(missing)).settings(), MPI_COMM_WORLD);
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("patch 'baffle' has no condition"), std::string::npos)
        << e.what();
  }
  const std::string noOutlet = replaced("{type: pressure_outlet, pressure: 1.0e5}", "{type: wall}");
  try {
    GasSolver gas(GasConfig(YAML::Load(noOutlet)).settings(), MPI_COMM_WORLD);
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("pressure_outlet"), std::string::npos) << e.what();
  }
  // The valid file builds a solver.
  GasSolver gas(GasConfig(YAML::Load(kValid)).settings(), MPI_COMM_WORLD);
  EXPECT_GT(gas.mesh().nGlobalCells(), 0);
}

// A fluid region with no face to the fluid that reaches a pressure outlet has no pressure level: refused
// with the pocket's size and place, on staircase and cut cells (a hollow shell of solid in a box of fluid
// around a fluid core; cells 0.1 m, the shell two cells thick).
TEST(GasConfig, EnclosedPocketsAreRefused) {
  auto pocketCase = [](const std::string& walls) {
    return "mesh: {origin: [0, 0, 0], lengths: [1, 1, 1], cells: [10, 10, 10], walls: " + walls + "}\n"
           "geometry:\n"
           "  - shape: {box: {min: [0, 0, 0], max: [1, 1, 1]}}\n"
           "  - {op: cut, shape: {box: {min: [0.2, 0.2, 0.2], max: [0.8, 0.8, 0.8]}}}\n"
           "  - shape: {box: {min: [0.4, 0.4, 0.4], max: [0.6, 0.6, 0.6]}}\n"
           "gas: {density: 1.2, viscosity: 1.8e-5}\n"
           "boundaries: {zmax: {type: pressure_outlet}, zmin: {type: wall}, xmin: {type: wall}, xmax: {type: wall},"
           " ymin: {type: wall}, ymax: {type: wall}, walls: {type: wall}}\n";
  };
  for (const std::string walls : {"staircase", "cut_cells"}) {
    try {
      GasSolver gas(GasConfig(YAML::Load(pocketCase(walls))).settings(), MPI_COMM_WORLD);
      ADD_FAILURE() << walls << ": expected ConfigError";
    } catch (const ConfigError& e) {
      expectError(e.what(), {"geometry", "8 fluid cell(s), the first at (0.45, 0.45, 0.45), share", "1 such pocket(s), 8 cells",
                             "pressure_outlet"});
    }
  }
  // The same box without the core: one region, reached by the outlet.
  std::string open = pocketCase("cut_cells");
  open.erase(open.find("  - shape: {box: {min: [0.4"), std::string("  - shape: {box: {min: [0.4, 0.4, 0.4], max: [0.6, 0.6, 0.6]}}\n").size());
  GasSolver gas(GasConfig(YAML::Load(open)).settings(), MPI_COMM_WORLD);
  EXPECT_EQ(gas.mesh().nFluidRegions(), 1);
}
