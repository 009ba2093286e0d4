#include "liggghts_instance.h"

#include <csignal>
#include <cstring>

#include "input.h"
#include "lammps.h"
#include "signal_handling.h"

namespace parcelflow::coupling {

LiggghtsInstance::LiggghtsInstance(MPI_Comm world, const std::vector<std::string>& arguments) {
  MPI_Comm_dup(world, &comm_);
  std::vector<std::string> storage;
  storage.reserve(arguments.size() + 1);
  storage.emplace_back("parcelflow");
  storage.insert(storage.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& s : storage) argv.push_back(s.data());
  argv.push_back(nullptr);
  lmp_ = new LAMMPS_NS::LAMMPS(static_cast<int>(storage.size()), argv.data(), comm_);
}

LiggghtsInstance::~LiggghtsInstance() {
  delete lmp_;
  MPI_Comm_free(&comm_);
}

void LiggghtsInstance::runInputFile() { lmp_->input->file(); }

void LiggghtsInstance::runFile(const std::string& path) { lmp_->input->file(path.c_str()); }

void LiggghtsInstance::command(const std::string& line) { lmp_->input->one(line.c_str()); }

void LiggghtsInstance::installSignalHandlers() {
  struct sigaction interrupt {};
  interrupt.sa_handler = LAMMPS_NS::SignalHandler::int_handler;
  sigaction(SIGINT, &interrupt, nullptr);
  // Open MPI turns a SIGINT to mpirun into SIGTERM to its children: treat both alike.
  sigaction(SIGTERM, &interrupt, nullptr);
  struct sigaction restart {};
  restart.sa_handler = LAMMPS_NS::SignalHandler::usr1_handler;
  sigaction(SIGUSR1, &restart, nullptr);
}

}  // namespace parcelflow::coupling
