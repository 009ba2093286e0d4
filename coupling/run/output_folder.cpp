#include "coupling/run/output_folder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "coupling/run/broadcast_text.h"
#include "cfd/base/config_error.hpp"

namespace parcelflow::coupling {

namespace fs = std::filesystem;

namespace {

// What a run writes into its folder that a later fresh run would not overwrite.
const std::regex kStaleOutput(
    R"((fields|parcels|averages)_[0-9]+\.h5|(fields|parcels|averages)\.xdmf|averages\.csv|checkpoints)");

// "" when `folder` exists (or was created) and a file can be written in it, else why not.
std::string makeWritable(const fs::path& folder) {
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) return "cannot be created: " + error.message();
  if (!fs::is_directory(folder)) return "is not a folder";
  const fs::path probe = folder / ".parcelflow_write_test";
  const bool written = static_cast<bool>(std::ofstream(probe) << "x");
  fs::remove(probe, error);
  return written ? "" : "cannot be written";
}

// Moves the earlier run's outputs (and its monitors.csv) into folder/earlier_run_<k>/, the first free k, so
// that nothing written is lost; returns a warning naming what was there ("" if nothing).
std::string moveEarlierRun(const fs::path& folder) {
  std::vector<fs::path> earlier;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (std::regex_match(name, kStaleOutput) || name == "monitors.csv") earlier.push_back(entry.path());
  }
  if (earlier.empty()) return "";
  fs::path aside;
  for (int k = 1; aside.empty() || fs::exists(aside); ++k) aside = folder / ("earlier_run_" + std::to_string(k));
  fs::create_directory(aside);
  int snapshots = 0;
  std::string named;
  for (const auto& path : earlier) {
    const std::string name = path.filename().string();
    if (name.find('_') != std::string::npos && path.extension() == ".h5") ++snapshots;
    else named += (named.empty() ? "" : ", ") + name + (fs::is_directory(path) ? "/" : "");
    fs::rename(path, aside / name);
  }
  return folder.string() + " held an earlier run's output: moved " + std::to_string(snapshots) +
         " snapshot files (fields_*.h5, parcels_*.h5, averages_*.h5)" + (named.empty() ? "" : " and " + named) +
         " to " + aside.string() + " (to continue a run use --restart instead)";
}

// "" when this run may write into `folder` (then `lock` holds it for the run), else the error to report.
std::string claimFolder(const std::string& folder, const std::string& key, std::unique_ptr<FolderLock>& lock) {
  const std::string problem = makeWritable(folder);
  if (!problem.empty())
    return cfd::ConfigError(key, folder + " (" + problem + ")", "a folder that can be created and written").what();
  try {
    lock = std::make_unique<FolderLock>(folder);
  } catch (const std::system_error& e) {
    return cfd::ConfigError(key, folder + " (cannot be locked: " + e.what() + ")",
                            "a folder that can be written, on a file system with file locks (flock)")
        .what();
  }
  if (lock->held()) return "";
  const std::string holder = lock->holder().empty() ? "" : ", " + lock->holder() + ",";
  return cfd::ConfigError(key, folder + " (another parcelflow run" + holder + " is writing there)",
                          "a folder no other run is writing to: give another one, or wait until that run has ended")
      .what();
}

}  // namespace

FolderLock::FolderLock(const std::string& folder) {
  const std::string path = (fs::path(folder) / kFileName).string();
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);  // no program run from here holds it
  if (fd < 0) throw std::system_error(errno, std::generic_category(), "open " + path);
  if (::flock(fd, LOCK_EX | LOCK_NB) == 0) {
    fd_ = fd;
    char host[256] = "";
    ::gethostname(host, sizeof host - 1);
    // Through a second descriptor: closing it keeps the lock, which belongs to fd's open file (flock, unlike
    // fcntl locks).
    std::ofstream(path) << "pid " << ::getpid() << " on host " << host << "\n";
    return;
  }
  const int error = errno;
  ::close(fd);
  if (error != EWOULDBLOCK) throw std::system_error(error, std::generic_category(), "flock " + path);
  std::ifstream written(path);
  std::getline(written, holder_);
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

std::unique_ptr<FolderLock> prepareOutputFolder(const std::string& folder, const std::string& key, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::unique_ptr<FolderLock> lock;
  const std::string problem = broadcastText(rank == 0 ? claimFolder(folder, key, lock) : std::string(), 0, comm);
  if (!problem.empty()) throw cfd::ConfigError(problem);
  return lock;
}

void clearEarlierRun(const std::string& folder, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::string removed, problem;
  if (rank == 0) {
    try {
      removed = moveEarlierRun(folder);
    } catch (const fs::filesystem_error& e) {
      problem = e.what();
    }
  }
  problem = broadcastText(problem, 0, comm);
  if (!problem.empty())
    throw std::runtime_error(folder + " holds an earlier run's output that cannot be moved aside: " + problem);
  if (rank == 0 && !removed.empty()) std::printf("parcelflow: warning: %s\n", removed.c_str());
}

}  // namespace parcelflow::coupling
