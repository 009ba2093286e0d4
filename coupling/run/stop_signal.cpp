#include "stop_signal.h"

#include <csignal>
#include <cstdlib>

namespace parcelflow::coupling {

namespace {

volatile std::sig_atomic_t received = 0;

void raiseFlag(int signal) { received = signal; }

}  // namespace

void installStopSignalHandlers() {
  struct sigaction action {};
  action.sa_handler = raiseFlag;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  // Open MPI turns a SIGINT to mpirun into SIGTERM to its children: treat both alike.
  sigaction(SIGTERM, &action, nullptr);
}

int stopRequested(MPI_Comm comm) {
  int local = received, any = 0;
  MPI_Allreduce(&local, &any, 1, MPI_INT, MPI_MAX, comm);
  return any;
}

double mpirunKillDelay() {
  if (!std::getenv("OMPI_COMM_WORLD_SIZE")) return -1.0;
  const char* setting = std::getenv("OMPI_MCA_odls_base_sigkill_timeout");
  return setting ? std::atof(setting) : 1.0;
}

}  // namespace parcelflow::coupling
