// The output folder's lock: one run at a time writes into a folder, a second is refused with a ConfigError
// naming the key, the folder and the holder's pid; the lock ends with its holder, and moving an earlier run
// aside leaves the lock file alone.
#include <gtest/gtest.h>
#include <mpi.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "coupling/run/broadcast_text.h"
#include "cfd/base/config_error.hpp"
#include "coupling/run/output_folder.h"

namespace pc = parcelflow::coupling;
namespace fs = std::filesystem;

namespace {

// A new empty folder, the same on every rank, removed at the end of the test.
class TempFolder {
 public:
  TempFolder() {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    std::string made;
    if (rank == 0) {
      char pattern[] = "/tmp/pf_output_folder_XXXXXX";
      made = ::mkdtemp(pattern) ? pattern : "";
    }
    path = pc::broadcastText(made, 0, MPI_COMM_WORLD);
  }
  ~TempFolder() {
    MPI_Barrier(MPI_COMM_WORLD);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0) fs::remove_all(path);
  }
  std::string path;
};

bool isRankZero() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank == 0;
}

}  // namespace

TEST(FolderLock, OneHolderAtATimeUntilItEnds) {
  const TempFolder folder;
  ASSERT_FALSE(folder.path.empty());
  if (!isRankZero()) return;
  {
    const pc::FolderLock first(folder.path);
    ASSERT_TRUE(first.held());
    const pc::FolderLock second(folder.path);  // a second open file, as another process has
    EXPECT_FALSE(second.held());
    EXPECT_EQ(second.holder().rfind("pid " + std::to_string(::getpid()) + " on host ", 0), 0u) << second.holder();
  }
  EXPECT_TRUE(fs::exists(fs::path(folder.path) / pc::FolderLock::kFileName));  // it stays, released
  const pc::FolderLock after(folder.path);
  EXPECT_TRUE(after.held());
}

TEST(OutputFolder, ASecondRunIntoALockedFolderIsRefused) {
  const TempFolder folder;
  const std::string out = folder.path + "/output";
  auto lock = pc::prepareOutputFolder(out, "--output", MPI_COMM_WORLD);
  EXPECT_EQ(lock != nullptr, isRankZero());  // rank 0 holds it for the run
  try {
    pc::prepareOutputFolder(out, "output.folder", MPI_COMM_WORLD);
    FAIL() << "no ConfigError for a locked folder";
  } catch (const parcelflow::cfd::ConfigError& e) {
    const std::string message = e.what();
    for (const std::string& part : {std::string("output.folder = ") + out, std::string("another parcelflow run, pid "),
                                    std::string("is writing there"), std::string("give another one, or wait")})
      EXPECT_NE(message.find(part), std::string::npos) << message << "\nlacks: " << part;
  }
  lock.reset();
  EXPECT_NO_THROW(pc::prepareOutputFolder(out, "--output", MPI_COMM_WORLD));
}

TEST(OutputFolder, MovingAnEarlierRunAsideLeavesTheLock) {
  const TempFolder folder;
  const auto lock = pc::prepareOutputFolder(folder.path, "--output", MPI_COMM_WORLD);
  if (isRankZero()) std::ofstream(fs::path(folder.path) / "monitors.csv") << "time\n0\n";
  MPI_Barrier(MPI_COMM_WORLD);
  pc::clearEarlierRun(folder.path, MPI_COMM_WORLD);
  EXPECT_TRUE(fs::exists(fs::path(folder.path) / "earlier_run_1" / "monitors.csv"));
  EXPECT_TRUE(fs::exists(fs::path(folder.path) / pc::FolderLock::kFileName));
  EXPECT_FALSE(fs::exists(fs::path(folder.path) / "earlier_run_1" / pc::FolderLock::kFileName));
}
