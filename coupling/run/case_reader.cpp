#include "coupling/run/case_reader.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>

#include "cfd/base/config_error.hpp"
#include "cfd/base/number_text.hpp"
#include "coupling/drag/drag_law.hpp"
#include "cfd/io/yaml_duplicate_keys.hpp"
#include "cfd/io/yaml_section.hpp"

namespace parcelflow::coupling {

using cfd::ConfigError;
using cfd::Range;
using cfd::YamlSection;

namespace {

const std::vector<std::string> kCouplingTopLevelKeys = {"liggghts", "time", "coupling", "output", "monitors"};
// More DEM steps per gas step than this is a mistake in the steps' units (and near INT_MAX an overflow).
constexpr double kMaxDemStepsPerGasStep = 1e6;
constexpr double kMinGasFractionFloor = 0.01;


LiggghtsSettings readLiggghts(const YamlSection& s) {
  s.allowOnly({"script", "variables"});
  LiggghtsSettings l;
  l.script = s.text("script", std::nullopt);
  if (s.has("variables")) {
    const YamlSection vars = s.map("variables");
    vars.allowAnyKeys();  // the script's variable names
    for (const auto& name : vars.keys()) l.variables.emplace_back(name, vars.text(name, std::nullopt));
  }
  return l;
}

TimeSettings readTime(const YamlSection& s) {
  s.allowOnly({"end", "gas_step", "dem_step"});
  TimeSettings t;
  t.end = s.number("end", std::nullopt, Range::positive());
  t.gas_step = s.number("gas_step", std::nullopt, Range::positive());
  t.dem_step = s.number("dem_step", std::nullopt, Range::positive());
  const double ratio = t.gas_step / t.dem_step;
  if (ratio < 0.5 || std::abs(ratio - std::round(ratio)) > 1e-6 * ratio)
    s.fail("gas_step", "is " + std::to_string(ratio) + " DEM steps (time.dem_step = " + std::to_string(t.dem_step) +
                           "); it must be a whole number of DEM steps, at least 1");
  if (ratio > kMaxDemStepsPerGasStep)
    s.fail("gas_step", "is " + cfd::shortNumber(ratio) + " DEM steps (time.dem_step = " + cfd::shortNumber(t.dem_step) +
                           "); allowed are at most 1e6 DEM steps per gas step");
  if (t.gas_step > t.end * (1.0 + 1e-9))
    s.fail("gas_step", "is longer than time.end = " + cfd::shortNumber(t.end) + " s; allowed is gas_step <= end");
  return t;
}

GuardSettings readGuards(const YamlSection& s) {
  s.allowOnly({"max_cfl", "max_continuity_error", "max_parcel_loss"});
  GuardSettings g;
  g.max_cfl = s.number("max_cfl", g.max_cfl, Range::positive());
  g.max_continuity_error = s.number("max_continuity_error", g.max_continuity_error, Range::positive());
  g.max_parcel_loss = s.number("max_parcel_loss", g.max_parcel_loss, Range{0.0, 1.0, true, false});
  return g;
}

// coupling.filtered_drag belongs to the filtered law alone: required with it, refused with any other.
FilteredDragSettings readFilteredDrag(const YamlSection& s, const std::string& drag) {
  const std::string filtered = RadlSundaresanDrag::typeName;
  if (drag != filtered) {
    if (s.has("filtered_drag"))
      s.fail("filtered_drag", "is only read by coupling.drag: " + filtered + " (coupling.drag is " + drag +
                                  "); remove it or choose that law");
    return {};
  }
  if (!s.has("filtered_drag"))
    s.fail("filtered_drag", "is required by coupling.drag: " + filtered +
                                ", e.g. filtered_drag: {particle_density: 1500} (kg/m^3 of the real particles)");
  const YamlSection f = s.map("filtered_drag");
  f.allowOnly({"particle_density", "filter_cells"});
  FilteredDragSettings settings;
  settings.particle_density = f.number("particle_density", std::nullopt, Range::positive());
  // The filter averages over at least the resolved cell; wider filters (coarser than the mesh) are the
  // model's own variable, for a filter-size study at a fixed mesh.
  settings.filter_cells = f.number("filter_cells", settings.filter_cells, Range::closed(1.0, 10.0));
  return settings;
}

ClassCollisionSettings readClassCollisions(const YamlSection& s) {
  s.allowOnly({"restitution", "friction"});
  ClassCollisionSettings c;
  c.enabled = true;
  // no defaults: they are the LIGGGHTS script's values for collisions between the types
  c.restitution = s.number("restitution", std::nullopt, Range::closed(0.0, 1.0));
  c.friction = s.number("friction", std::nullopt, Range::nonNegative());
  return c;
}

CouplingSettings readCoupling(const YamlSection& s) {
  s.allowOnly({"drag", "filtered_drag", "kernel", "gas_fraction_floor", "excess_solids", "class_collisions", "guards"});
  CouplingSettings c;
  c.drag = s.word("drag", c.drag, dragLawNames());
  c.filtered_drag = readFilteredDrag(s, c.drag);
  // Below 0.01 over-filled cells give the gas Courant numbers of 100 and more (coupling/README.md).
  c.gas_fraction_floor =
      s.number("gas_fraction_floor", c.gas_fraction_floor, Range{kMinGasFractionFloor, 1.0, false, true});
  c.excess_solids = s.word("excess_solids", c.excess_solids, {"discard", "spill"});
  if (s.has("guards")) c.guards = readGuards(s.map("guards"));
  if (s.has("class_collisions")) c.class_collisions = readClassCollisions(s.map("class_collisions"));
  if (s.has("kernel")) {
    const YamlSection k = s.map("kernel");
    if (k.has("width"))
      k.fail("width", "was renamed to coupling.kernel.sharpness: it is the a of exp(-a |dx|^2/h^2) (paper eq. 8), "
                      "so a larger value makes the kernel narrower, not wider");
    k.allowOnly({"type", "sharpness", "radius", "length_scale", "parcel_scale", "boundary", "smoothing_length"});
    c.kernel.type = k.word("type", c.kernel.type, {"gaussian", "centroid"});
    c.kernel.sharpness = k.number("sharpness", c.kernel.sharpness, Range::positive());
    c.kernel.radius = k.integer("radius", c.kernel.radius, 1, 4);
    c.kernel.length_scale = k.word("length_scale", c.kernel.length_scale, {"cell_volume", "cell_axes"});
    c.kernel.parcel_scale = k.number("parcel_scale", c.kernel.parcel_scale, Range::closed(0.0, 4.0));
    c.kernel.boundary = k.word("boundary", c.kernel.boundary, {"truncate", "reflect"});
    c.kernel.smoothing_length = k.number("smoothing_length", c.kernel.smoothing_length, Range::nonNegative());
  }
  return c;
}

OutputSettings readOutput(const YamlSection& s) {
  s.allowOnly({"folder", "fields_interval", "parcels_interval", "checkpoint_interval", "monitor_interval",
               "progress_interval"});
  OutputSettings o;
  o.folder = s.text("folder", o.folder);
  o.fields_interval = s.number("fields_interval", o.fields_interval, Range::nonNegative());
  o.parcels_interval = s.number("parcels_interval", o.parcels_interval, Range::nonNegative());
  o.checkpoint_interval = s.number("checkpoint_interval", o.checkpoint_interval, Range::nonNegative());
  o.monitor_interval = s.number("monitor_interval", o.monitor_interval, Range::positive());
  o.progress_interval = s.number("progress_interval", o.progress_interval, Range::positive());
  return o;
}

MonitorSettings readMonitors(const YamlSection& s, const YAML::Node& node) {
  s.allowOnly({"pressure_planes", "bed_pressure_drop", "average"});
  MonitorSettings m;
  if (s.has("average")) {
    const YamlSection a = s.map("average");
    a.allowOnly({"start"});
    m.average_start = a.number("start", std::nullopt, Range::nonNegative());
    if (!s.has("pressure_planes"))
      s.fail("average", "needs monitors.pressure_planes (the averaged pressure profile is taken on them)");
  }
  if (s.has("pressure_planes")) {
    const YAML::Node planes = node["pressure_planes"];
    if (!planes.IsSequence() || planes.size() == 0)
      s.fail("pressure_planes", "must be a non-empty list of heights z [m]");
    m.pressure_planes = s.numbers("pressure_planes", planes.size(), Range::any());
  }
  if (s.has("bed_pressure_drop")) {
    const auto z = s.numbers("bed_pressure_drop", 2, Range::any());
    if (!(z[0] < z[1])) s.fail("bed_pressure_drop", "must be two heights [z_low, z_high] with z_low < z_high");
    m.bed_pressure_drop = {z[0], z[1]};
    m.has_bed_pressure_drop = true;
  }
  return m;
}

// The filtered law needs particles heavier than the gas (a terminal velocity) and gravity (its length scale).
void checkFilteredDragAgainstGas(const CouplingSettings& coupling, const cfd::GasProperties& gas) {
  if (coupling.drag != RadlSundaresanDrag::typeName) return;
  const std::string law = std::string("coupling.drag: ") + RadlSundaresanDrag::typeName;
  const double density = coupling.filtered_drag.particle_density;
  if (!(density > gas.density))
    throw ConfigError("coupling.filtered_drag.particle_density", cfd::shortNumber(density),
                      "a number > gas.density = " + cfd::shortNumber(gas.density) + " (" + law +
                          " needs the terminal velocity of particles heavier than the gas)");
  if (!(gas.gravity.norm() > 0.0))
    throw ConfigError("gas.gravity",
                      "[" + cfd::shortNumber(gas.gravity[0]) + ", " + cfd::shortNumber(gas.gravity[1]) + ", " +
                          cfd::shortNumber(gas.gravity[2]) + "]",
                      "a non-zero vector with " + law + " (its filter size is measured in v_t^2 / |g|)");
}

}  // namespace

CaseSettings readCouplingSettings(const YAML::Node& root) {
  const YamlSection top(root, "");
  std::vector<std::string> allowed = kCouplingTopLevelKeys;
  for (const auto& key : cfd::GasConfig::ownedTopLevelKeys()) allowed.push_back(key);
  top.allowOnly(allowed);
  CaseSettings c;
  c.liggghts = readLiggghts(top.map("liggghts"));
  c.time = readTime(top.map("time"));
  if (top.has("coupling")) c.coupling = readCoupling(top.map("coupling"));
  if (top.has("output")) c.output = readOutput(top.map("output"));
  if (top.has("monitors")) c.monitors = readMonitors(top.map("monitors"), root["monitors"]);
  return c;
}

CaseDefinition readCase(const std::string& case_folder) {
  const std::string path = case_folder + "/case.yaml";
  if (!std::filesystem::is_regular_file(path) || !std::ifstream(path))
    throw ConfigError("cannot read '" + path + "': a case folder must contain case.yaml, a readable file");
  cfd::checkNoDuplicateKeys(path);
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw ConfigError(path + " is not valid YAML: " + e.what());
  }
  CaseDefinition c;
  c.folder = case_folder;
  c.settings = readCouplingSettings(root);
  c.gas = cfd::GasConfig(root, case_folder).settings();
  checkFilteredDragAgainstGas(c.settings.coupling, c.gas.gas);
  const std::string script = case_folder + "/" + c.settings.liggghts.script;
  if (!std::filesystem::is_regular_file(script) || !std::ifstream(script))
    throw ConfigError("liggghts.script", c.settings.liggghts.script,
                      "a readable file, path relative to the case folder (cannot read '" + script + "')");
  if (std::filesystem::file_size(script) == 0)
    throw ConfigError("liggghts.script", c.settings.liggghts.script,
                      "a LIGGGHTS input script that sets up the parcels ('" + script + "' is empty)");
  return c;
}

void applyEndTime(TimeSettings& time, double end, double start) {
  const double value = end > 0.0 ? end : time.end;
  if (value < start + time.gas_step * (1.0 - 1e-9))
    throw ConfigError(end > 0.0 ? "--end" : "time.end", cfd::shortNumber(value) + " s",
                      "at least one gas step (time.gas_step = " + cfd::shortNumber(time.gas_step) + " s)" +
                          (start > 0.0 ? " after the checkpoint's time " + cfd::shortNumber(start) + " s" : ""));
  time.end = value;
}

int TimeSettings::demStepsPerGasStep() const { return static_cast<int>(std::lround(gas_step / dem_step)); }

}  // namespace parcelflow::coupling
