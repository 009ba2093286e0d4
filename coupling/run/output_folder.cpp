#include "output_folder.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>
#include <vector>

#include "cfd/config_error.hpp"

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

// Removes the earlier run's outputs; returns a warning naming what was there ("" if nothing).
std::string removeStaleOutput(const fs::path& folder) {
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(folder))
    if (std::regex_match(entry.path().filename().string(), kStaleOutput)) stale.push_back(entry.path());
  const std::string overwritten = fs::exists(folder / "monitors.csv") ? "; its monitors.csv is overwritten" : "";
  if (stale.empty())
    return overwritten.empty() ? "" : folder.string() + " held an earlier run's output" + overwritten;
  int snapshots = 0;
  std::string named;
  for (const auto& path : stale) {
    const std::string name = path.filename().string();
    if (name.find('_') != std::string::npos && path.extension() == ".h5") ++snapshots;
    else named += (named.empty() ? "" : ", ") + name + (fs::is_directory(path) ? "/" : "");
    fs::remove_all(path);
  }
  return folder.string() + " held an earlier run's output: removed " + std::to_string(snapshots) +
         " snapshot files (fields_*.h5, parcels_*.h5, averages_*.h5)" + (named.empty() ? "" : " and " + named) +
         overwritten + " (to continue a run use --restart instead)";
}

std::string broadcast(std::string text, MPI_Comm comm) {
  int size = static_cast<int>(text.size());
  MPI_Bcast(&size, 1, MPI_INT, 0, comm);
  text.resize(size);
  MPI_Bcast(text.data(), size, MPI_CHAR, 0, comm);
  return text;
}

}  // namespace

void prepareOutputFolder(const std::string& folder, const std::string& key, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const std::string problem = broadcast(rank == 0 ? makeWritable(folder) : std::string(), comm);
  if (!problem.empty())
    throw cfd::ConfigError(key, folder + " (" + problem + ")", "a folder that can be created and written");
}

void clearEarlierRun(const std::string& folder, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::string removed, problem;
  if (rank == 0) {
    try {
      removed = removeStaleOutput(folder);
    } catch (const fs::filesystem_error& e) {
      problem = e.what();
    }
  }
  problem = broadcast(problem, comm);
  if (!problem.empty())
    throw std::runtime_error(folder + " holds an earlier run's output that cannot be removed: " + problem);
  if (rank == 0 && !removed.empty()) std::printf("parcelflow: warning: %s\n", removed.c_str());
}

}  // namespace parcelflow::coupling
