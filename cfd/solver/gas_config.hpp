#pragma once
// Reads the gas part of case.yaml: the top-level keys `mesh`, `geometry`, `gas`, `boundaries`,
// `inlet_regions` and `solver`. Other top-level keys (`coupling`, `output`, `time`, ...) belong to the
// coupling layer and are left alone; inside the gas keys every unknown key, wrong type or out-of-range
// value throws ConfigError naming the key path, the value and what is allowed.
#include <yaml-cpp/yaml.h>

#include "cfd/solver/gas_settings.hpp"

namespace parcelflow::cfd {

class YamlSection;

class GasConfig {
 public:
  // `root` is the parsed case.yaml (or any map holding the gas keys); STL files named in it are relative
  // to `caseFolder`.
  explicit GasConfig(const YAML::Node& root, const std::string& caseFolder = ".");
  static GasConfig fromFile(const std::string& path);

  const GasSettings& settings() const { return settings_; }

  // Top-level keys read here; the coupling layer checks the remaining ones itself.
  static const std::vector<std::string>& ownedTopLevelKeys();

 private:
  MeshSettings readMesh(const YamlSection& s) const;
  Geometry readGeometry(const YamlSection& top) const;
  Geometry readShapeList(const YamlSection& parent, const std::string& key) const;
  static GasProperties readGas(const YamlSection& s);
  static std::vector<BoundarySettings> readBoundaries(const YamlSection& s);
  std::vector<InletRegionSettings> readInletRegions(const YamlSection& top) const;
  static SolverSettings readSolver(const YamlSection& s);
  // pressure: the pressure solver, which keeps its preconditioner over steps (preconditioner_reuse) and
  // solves once per PISO corrector (final_rel_tol for the last one).
  static LinearSolverSettings readLinearSolver(const YamlSection& s, LinearSolverSettings fallback,
                                               bool pressure);
  // criterion and the tolerance keys of a linear solver map (each allowed only with its criterion).
  static void readStoppingCriterion(const YamlSection& s, LinearSolverSettings& l, bool pressure);
  std::string caseFolder_;
  GasSettings settings_;
};

}  // namespace parcelflow::cfd
