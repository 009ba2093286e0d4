// Checkpoints of a coupled run (DESIGN section 10). One checkpoint is one folder
//   OUTPUT/checkpoints/step_<gas step>/  dem.restart (LIGGGHTS write_restart), gas.h5 (cfd/output/gas_checkpoint.hpp),
//                                        loop.yaml (the loop's state, the case's settings, the id)
// under one id ("<gas step>-<random hex>"): gas.h5 carries it as an attribute, loop.yaml names it and the
// size and FNV-1a hash of dem.restart, so parts of two checkpoints are never combined. The folder is written
// under a temporary name and renamed when complete (a crash during a write leaves the previous checkpoints
// as they were); the last two are kept.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "coupling/run/run_counters.h"

namespace parcelflow::coupling {

// The time loop's own state: what a restarted run needs besides the gas and the DEM.
struct LoopState {
  long step = 0;  // gas steps done
  double time = 0.0;
  double next_monitor = 0.0, next_fields = 0.0, next_parcels = 0.0, next_checkpoint = 0.0;
  long dem_step = 0;         // LIGGGHTS' step counter
  long initial_parcels = 0;  // at the start of the first run
  long parcels = 0;          // at the checkpoint
  long monitor_bytes = 0;    // monitors.csv's size
  std::vector<double> field_times;  // snapshots written
  int parcel_snapshots = 0;
  RunCounters counters;  // summed over ranks
  std::map<std::string, std::vector<double>> averages;  // time-average accumulators by name
};

// The settings of case.yaml that a restart must not change, flattened to "key.path" -> value text: all of it
// but time.end, the output keys, the solver's iteration controls and the blow-up guard's limits.
std::map<std::string, std::string> restartRelevantSettings(const std::string& case_yaml);

struct CheckpointPaths {
  std::string folder, dem, gas, loop;
  explicit CheckpointPaths(const std::string& folder);
};

// Rank 0: makes the temporary folder for a checkpoint at `step` and returns the id and paths; every rank gets
// them (collective).
struct CheckpointDraft {
  std::string id;
  CheckpointPaths partial, final;
};
CheckpointDraft beginCheckpoint(const std::string& output_folder, long step, MPI_Comm comm);
// Rank 0: writes loop.yaml (last), renames the folder into place and removes all but the last two.
void commitCheckpoint(const CheckpointDraft& draft, const LoopState& loop,
                      const std::map<std::string, std::string>& settings, MPI_Comm comm);

// A checkpoint read back: its id, loop state and settings; throws cfd::ConfigError naming the file when it is
// missing, incomplete, or dem.restart does not match the size and hash loop.yaml recorded. Every rank reads.
struct Checkpoint {
  std::string id;
  CheckpointPaths paths;
  LoopState loop;
  std::map<std::string, std::string> settings;
};
Checkpoint readCheckpoint(const std::string& folder);

// Throws cfd::ConfigError listing every setting that differs between the checkpoint and the case.
// loop.time must be loop.step gas steps (a hand-edited or damaged loop.yaml would start the loop elsewhere)
void checkLoopTime(const Checkpoint& checkpoint, double gas_step);
void checkSameSettings(const Checkpoint& checkpoint, const std::map<std::string, std::string>& case_settings);
// The output folder a restart continues must hold the series the checkpoint's run wrote (monitors.csv up to
// the checkpoint, every parcel, field and average snapshot before it); throws cfd::ConfigError naming the
// first file that is missing, before LIGGGHTS starts.
void checkOutputSeries(const Checkpoint& checkpoint, const std::string& output_folder);

}  // namespace parcelflow::coupling
