// The output folder of a run. Before any work it must be a folder that can be created and written (else a
// cfd::ConfigError naming `key`, on every rank alike). A fresh run (not continuing a checkpoint) in a folder
// that holds an earlier run's output then moves that run's snapshot series, XDMF indexes, averages.csv,
// checkpoints and monitors.csv into OUTPUT/earlier_run_<k>/ (nothing written is lost, and the new series
// does not sit beside stale files), and says on the terminal what it moved; the loop calls that once
// everything is checked and LIGGGHTS has run the script, just before the first output file is written.
#pragma once

#include <mpi.h>

#include <string>

namespace parcelflow::coupling {

void prepareOutputFolder(const std::string& folder, const std::string& key, MPI_Comm comm);
void clearEarlierRun(const std::string& folder, MPI_Comm comm);  // collective

}  // namespace parcelflow::coupling
