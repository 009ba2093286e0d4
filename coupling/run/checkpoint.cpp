#include "coupling/run/checkpoint.h"

#include <mpi.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include "coupling/run/broadcast_text.h"
#include "cfd/base/config_error.hpp"
#include "cfd/io/hdf5_file.hpp"
#include "cfd/base/number_text.hpp"

namespace parcelflow::coupling {

using cfd::exactNumber;

namespace fs = std::filesystem;
using cfd::ConfigError;

namespace {

const char* const kStepPrefix = "step_";
const char* const kPartialPrefix = ".partial_step_";
const char* const kRetiredPrefix = ".retired_";

// Deletes a checkpoint folder so that no half-deleted folder keeps a complete checkpoint's name: a kill
// during remove_all would otherwise leave step_<N> without gas.h5. The rename is atomic; what a kill leaves
// of a .retired_ folder is removed when the next checkpoint is committed.
void retire(const fs::path& folder) {
  if (!fs::exists(folder)) return;
  const fs::path retired = folder.parent_path() / (kRetiredPrefix + folder.filename().string());
  fs::remove_all(retired);
  fs::rename(folder, retired);
  fs::remove_all(retired);
}

// Keys a restart may change: when to stop, what and how often to write, how hard the solvers iterate, when
// the blow-up guard stops.
bool mayChangeOnRestart(const std::string& key) {
  return key == "time.end" || key.rfind("output.", 0) == 0 || key.rfind("solver.", 0) == 0 ||
         key.rfind("coupling.guards.", 0) == 0;
}

void flatten(const YAML::Node& node, const std::string& prefix, std::map<std::string, std::string>& out) {
  if (node.IsMap()) {
    for (const auto& kv : node) flatten(kv.second, prefix.empty() ? kv.first.as<std::string>()
                                                                   : prefix + "." + kv.first.as<std::string>(), out);
  } else if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) flatten(node[i], prefix + "[" + std::to_string(i) + "]", out);
  } else if (!mayChangeOnRestart(prefix)) {
    out[prefix] = node.IsNull() ? "" : node.as<std::string>();
  }
}

// FNV-1a 64 of a file and its size: a mismatched or cut dem.restart is found before LIGGGHTS reads it.
std::pair<long, std::string> fileDigest(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path, "missing", "the LIGGGHTS restart of the checkpoint");
  std::uint64_t h = 1469598103934665603ull;
  long size = 0;
  char buf[1 << 16];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    for (std::streamsize k = 0; k < in.gcount(); ++k) {
      h ^= static_cast<unsigned char>(buf[k]);
      h *= 1099511628211ull;
    }
    size += static_cast<long>(in.gcount());
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return {size, hex};
}

}  // namespace

CheckpointPaths::CheckpointPaths(const std::string& f)
    : folder(f), dem(f + "/dem.restart"), gas(f + "/gas.h5"), loop(f + "/loop.yaml") {}

std::map<std::string, std::string> restartRelevantSettings(const std::string& case_yaml) {
  std::map<std::string, std::string> out;
  flatten(YAML::LoadFile(case_yaml), "", out);
  return out;
}

CheckpointDraft beginCheckpoint(const std::string& output_folder, long step, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  char name[32];
  std::snprintf(name, sizeof name, "%09ld", step);
  const fs::path root = fs::path(output_folder) / "checkpoints";
  std::string id;
  if (rank == 0) {
    std::random_device random;
    char tag[32];
    std::snprintf(tag, sizeof tag, "%ld-%08x%08x", step, random(), random());
    id = tag;
    fs::create_directories(root);
    fs::remove_all(root / (kPartialPrefix + std::string(name)));
    fs::create_directories(root / (kPartialPrefix + std::string(name)));
  }
  id = broadcastText(id, 0, comm);
  return {id, CheckpointPaths((root / (kPartialPrefix + std::string(name))).string()),
          CheckpointPaths((root / (kStepPrefix + std::string(name))).string())};
}

void commitCheckpoint(const CheckpointDraft& draft, const LoopState& loop,
                      const std::map<std::string, std::string>& settings, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  MPI_Barrier(comm);  // every rank has closed its part of gas.h5 and dem.restart
  if (rank == 0) {
    const auto [dem_size, dem_hash] = fileDigest(draft.partial.dem);
    YAML::Emitter y;
    y << YAML::BeginMap << YAML::Key << "checkpoint_id" << YAML::Value << draft.id;
    y << YAML::Key << "dem_restart" << YAML::Value << YAML::BeginMap << YAML::Key << "bytes" << YAML::Value
      << dem_size << YAML::Key << "fnv1a64" << YAML::Value << dem_hash << YAML::EndMap;
    y << YAML::Key << "loop" << YAML::Value << YAML::BeginMap;
    y << YAML::Key << "step" << YAML::Value << loop.step;
    y << YAML::Key << "time" << YAML::Value << exactNumber(loop.time);
    for (const auto& [key, value] : std::vector<std::pair<const char*, double>>{
             {"next_monitor", loop.next_monitor}, {"next_fields", loop.next_fields},
             {"next_parcels", loop.next_parcels}, {"next_checkpoint", loop.next_checkpoint}})
      y << YAML::Key << key << YAML::Value << exactNumber(value);
    y << YAML::Key << "dem_step" << YAML::Value << loop.dem_step << YAML::Key << "initial_parcels" << YAML::Value
      << loop.initial_parcels << YAML::Key << "parcels" << YAML::Value << loop.parcels << YAML::Key
      << "monitor_bytes" << YAML::Value << loop.monitor_bytes << YAML::Key << "parcel_snapshots" << YAML::Value
      << loop.parcel_snapshots;
    y << YAML::Key << "field_times" << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (double t : loop.field_times) y << exactNumber(t);
    y << YAML::EndSeq;
    RunCounters counters = loop.counters;
    y << YAML::Key << "counters" << YAML::Value << YAML::BeginMap;
    for (const auto& [name, value] : counters.perRank()) y << YAML::Key << name << YAML::Value << *value;
    for (const auto& [name, value] : counters.global()) y << YAML::Key << name << YAML::Value << *value;
    y << YAML::Key << "min_gas_fraction" << YAML::Value << exactNumber(counters.min_gas_fraction) << YAML::EndMap;
    y << YAML::Key << "averages" << YAML::Value << YAML::BeginMap;
    for (const auto& [name, values] : loop.averages) {
      y << YAML::Key << name << YAML::Value << YAML::Flow << YAML::BeginSeq;
      for (double v : values) y << exactNumber(v);
      y << YAML::EndSeq;
    }
    y << YAML::EndMap << YAML::EndMap;
    y << YAML::Key << "settings" << YAML::Value << YAML::BeginMap;
    for (const auto& [key, value] : settings) y << YAML::Key << key << YAML::Value << value;
    y << YAML::EndMap << YAML::EndMap;
    {
      std::ofstream out(draft.partial.loop);
      out << y.c_str() << "\n";
      out.close();
      if (!out) throw std::runtime_error("cannot write " + draft.partial.loop);
    }
    retire(draft.final.folder);
    fs::rename(draft.partial.folder, draft.final.folder);
    // Keep the newest two complete checkpoints; remove what a kill left of retired ones.
    std::vector<fs::path> complete, leftovers;
    for (const auto& entry : fs::directory_iterator(fs::path(draft.final.folder).parent_path())) {
      const std::string name = entry.path().filename().string();
      if (name.rfind(kStepPrefix, 0) == 0) complete.push_back(entry.path());
      if (name.rfind(kRetiredPrefix, 0) == 0) leftovers.push_back(entry.path());
    }
    for (const auto& folder : leftovers) fs::remove_all(folder);
    std::sort(complete.begin(), complete.end());
    for (std::size_t k = 0; k + 2 < complete.size(); ++k) retire(complete[k]);
  }
  MPI_Barrier(comm);
}

Checkpoint readCheckpoint(const std::string& folder) {
  Checkpoint c{"", CheckpointPaths(folder), {}, {}};
  if (!fs::is_directory(folder))
    throw ConfigError("--restart", folder, "a checkpoint folder, OUTPUT/checkpoints/step_<N>");
  if (!fs::exists(c.paths.loop))
    throw ConfigError(c.paths.loop, "missing", "the loop state every complete checkpoint has (an incomplete checkpoint?)");
  YAML::Node y;
  try {
    y = YAML::LoadFile(c.paths.loop);
    c.id = y["checkpoint_id"].as<std::string>();
    const YAML::Node l = y["loop"];
    LoopState& s = c.loop;
    s.step = l["step"].as<long>();
    s.time = l["time"].as<double>();
    s.next_monitor = l["next_monitor"].as<double>();
    s.next_fields = l["next_fields"].as<double>();
    s.next_parcels = l["next_parcels"].as<double>();
    s.next_checkpoint = l["next_checkpoint"].as<double>();
    s.dem_step = l["dem_step"].as<long>();
    s.initial_parcels = l["initial_parcels"].as<long>();
    s.parcels = l["parcels"].as<long>();
    s.monitor_bytes = l["monitor_bytes"].as<long>();
    s.parcel_snapshots = l["parcel_snapshots"].as<int>();
    s.field_times = l["field_times"].as<std::vector<double>>();
    for (auto& [name, value] : s.counters.perRank()) *value = l["counters"][name].as<long>();
    for (auto& [name, value] : s.counters.global()) *value = l["counters"][name].as<long>();
    s.counters.min_gas_fraction = l["counters"]["min_gas_fraction"].as<double>();
    for (const auto& kv : l["averages"]) s.averages[kv.first.as<std::string>()] = kv.second.as<std::vector<double>>();
    for (const auto& kv : y["settings"]) c.settings[kv.first.as<std::string>()] = kv.second.as<std::string>();
  } catch (const YAML::Exception& e) {
    throw ConfigError(c.paths.loop, "unreadable (" + std::string(e.what()) + ")", "a loop.yaml written by parcelflow");
  }
  if (!fs::exists(c.paths.gas)) throw ConfigError(c.paths.gas, "missing", "the gas state of checkpoint " + c.id);
  std::string gas_id;
  try {
    gas_id = cfd::Hdf5Reader(c.paths.gas).textAttribute("checkpoint_id");
  } catch (const std::runtime_error& e) {
    throw ConfigError(c.paths.gas, std::string("unreadable (") + e.what() + ")",
                      "the gas state of checkpoint " + c.id + ", an HDF5 file written by parcelflow");
  }
  if (gas_id != c.id)
    throw ConfigError(c.paths.gas + ": checkpoint_id", gas_id,
                      "the id of the checkpoint it belongs to, " + c.id +
                          ": parts of different checkpoints must not be combined");
  const auto [size, hash] = fileDigest(c.paths.dem);
  const long expected_size = y["dem_restart"]["bytes"].as<long>();
  const std::string expected_hash = y["dem_restart"]["fnv1a64"].as<std::string>();
  if (size != expected_size || hash != expected_hash)
    throw ConfigError(c.paths.dem, std::to_string(size) + " bytes, FNV-1a " + hash,
                      "the file of checkpoint " + c.id + " (" + std::to_string(expected_size) + " bytes, FNV-1a " +
                          expected_hash + "): parts of different checkpoints must not be combined");
  return c;
}

void checkLoopTime(const Checkpoint& checkpoint, double gas_step) {
  const LoopState& l = checkpoint.loop;
  const double expected = static_cast<double>(l.step) * gas_step;  // the loop's own time: step * gas step
  if (l.step < 0 || !(std::abs(l.time - expected) <= 1e-9 * std::max(expected, gas_step)))
    throw ConfigError(checkpoint.paths.loop + ": loop.time", exactNumber(l.time),
                      "loop.step x time.gas_step = " + exactNumber(expected) + " s (step " +
                          std::to_string(l.step) + "), as parcelflow writes a checkpoint");
}

void checkSameSettings(const Checkpoint& checkpoint, const std::map<std::string, std::string>& now) {
  std::string differences;
  auto note = [&](const std::string& key, const std::string& then, const std::string& here) {
    differences += "\n  " + key + ": checkpoint " + (then.empty() ? "(not set)" : then) + ", case " +
                   (here.empty() ? "(not set)" : here);
  };
  for (const auto& [key, value] : checkpoint.settings) {
    const auto it = now.find(key);
    const std::string here = it == now.end() ? "" : it->second;
    if (here != value) note(key, value, here);
  }
  for (const auto& [key, value] : now)
    if (!checkpoint.settings.count(key)) note(key, "", value);
  if (!differences.empty())
    throw ConfigError("--restart " + checkpoint.paths.folder + ": the case's settings differ from the checkpoint's "
                      "(only time.end, output.*, solver.* and coupling.guards.* may change on a restart):" +
                      differences);
}

void checkOutputSeries(const Checkpoint& checkpoint, const std::string& output_folder) {
  const std::string allowed = "the file checkpoint " + checkpoint.id +
                              "'s run wrote there: continue in that run's output folder (output.folder or --output)";
  const fs::path folder(output_folder);
  const fs::path monitors = folder / "monitors.csv";
  if (!fs::is_regular_file(monitors)) throw ConfigError(monitors.string(), "missing", allowed);
  if (static_cast<long>(fs::file_size(monitors)) < checkpoint.loop.monitor_bytes)
    throw ConfigError(monitors.string(), std::to_string(fs::file_size(monitors)) + " bytes",
                      "at least the " + std::to_string(checkpoint.loop.monitor_bytes) +
                          " bytes written at checkpoint " + checkpoint.id);
  auto requireSeries = [&](const std::string& name, std::size_t snapshots) {
    for (std::size_t i = 0; i < snapshots; ++i) {
      const fs::path file = folder / cfd::seriesFileName(name, i);
      if (!fs::is_regular_file(file)) throw ConfigError(file.string(), "missing", allowed);
    }
  };
  requireSeries(cfd::series::parcels, static_cast<std::size_t>(checkpoint.loop.parcel_snapshots));
  requireSeries(cfd::series::fields, checkpoint.loop.field_times.size());
  const auto averages = checkpoint.loop.averages.find("field_times");
  if (averages != checkpoint.loop.averages.end()) requireSeries(cfd::series::averages, averages->second.size());
}

}  // namespace parcelflow::coupling
