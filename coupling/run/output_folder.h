// The output folder of a run. Before any work it must be a folder that can be created and written, and no
// other parcelflow run may be writing there (else a cfd::ConfigError naming `key`, on every rank alike): a run
// locks its folder from prepareOutputFolder until it ends, so that a second run cannot move the first's
// files aside while the first writes them. A fresh run (not continuing a checkpoint) in a folder
// that holds an earlier run's output then moves that run's snapshot series, XDMF indexes, averages.csv,
// checkpoints and monitors.csv into OUTPUT/earlier_run_<k>/ (nothing written is lost, and the new series
// does not sit beside stale files), and says on the terminal what it moved; the loop calls that once
// everything is checked and LIGGGHTS has run the script, just before the first output file is written.
#pragma once

#include <mpi.h>

#include <memory>
#include <string>

namespace parcelflow::coupling {

// An exclusive lock on FOLDER/.parcelflow.lock (flock), held while the object lives or until the process
// ends in any way: the kernel releases it, so a killed run leaves no stale lock. The file itself stays (it
// is not an output: clearEarlierRun leaves it) and names the holder's pid and host.
class FolderLock {
 public:
  static constexpr const char* kFileName = ".parcelflow.lock";
  // Takes the lock unless another holder has it; throws std::system_error if the file cannot be opened or
  // locked (a file system without flock).
  explicit FolderLock(const std::string& folder);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  bool held() const { return fd_ >= 0; }
  // When not held: the holder as it wrote itself into the file ("pid 4711 on host node1"; "" if not yet).
  const std::string& holder() const { return holder_; }

 private:
  int fd_ = -1;
  std::string holder_;
};

// Checks the folder and locks it for this run: the lock is held while the result lives (rank 0 holds it;
// nullptr on the other ranks). Collective.
std::unique_ptr<FolderLock> prepareOutputFolder(const std::string& folder, const std::string& key, MPI_Comm comm);
void clearEarlierRun(const std::string& folder, MPI_Comm comm);  // collective

}  // namespace parcelflow::coupling
