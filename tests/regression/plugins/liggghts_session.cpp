#include "tests/regression/plugins/liggghts_session.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

namespace parcelflow::plugins::testing {

std::string scratch_dir(const std::string& name)
{
  std::string dir;
  if (rank() == 0) {
    const char* base = std::getenv("TMPDIR");
    dir = std::string(base ? base : "/tmp") + "/parcelflow_plugins_" + name + "_" + std::to_string(getpid());
    std::filesystem::create_directories(dir);
  }
  int n = static_cast<int>(dir.size());
  MPI_Bcast(&n, 1, MPI_INT, 0, MPI_COMM_WORLD);
  dir.resize(n);
  MPI_Bcast(dir.data(), n, MPI_CHAR, 0, MPI_COMM_WORLD);
  return dir;
}

void remove_scratch_dir(const std::string& dir)
{
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank() == 0 && !::testing::Test::HasFailure()) std::filesystem::remove_all(dir);
  MPI_Barrier(MPI_COMM_WORLD);
}

Session::Session(const std::string& log)
{
  MPI_Comm_dup(MPI_COMM_WORLD, &comm_);
  // Not "-screen none": LIGGGHTS 3.8 writes to a NULL screen in Region::reset_random (used by fix insert/pack)
  // and crashes; /dev/null keeps the screen quiet and valid.
  std::vector<std::string> args = {"liggghts", "-screen", "/dev/null", "-log", log};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  lmp_ = new LAMMPS_NS::LAMMPS(static_cast<int>(argv.size()), argv.data(), comm_);
  register_styles(lmp_);
}

Session::~Session()
{
  delete lmp_;
  MPI_Comm_free(&comm_);
}

}  // namespace parcelflow::plugins::testing
