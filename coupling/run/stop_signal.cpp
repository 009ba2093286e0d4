#include "coupling/run/stop_signal.h"

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>

namespace parcelflow::coupling {

namespace {

volatile std::sig_atomic_t received = 0;

void raiseFlag(int signal) { received = signal; }

char start_up_message[512];
int start_up_message_length = 0;

// async-signal-safe: write(2) and _exit(2) only
void stopDuringStartUp(int signal) {
  if (start_up_message_length > 0) (void)!write(STDERR_FILENO, start_up_message, start_up_message_length);
  _exit(128 + signal);
}

void installHandler(void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  // Open MPI turns a SIGINT to mpirun into SIGTERM to its children: treat both alike.
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace

void installStartUpSignalHandlers(int rank) {
  const int n = std::snprintf(start_up_message, sizeof start_up_message,
                              "parcelflow: rank %d: stopped by a signal before the coupled run started (while the "
                              "case's LIGGGHTS script or the set-up ran): no checkpoint exists yet; run again to "
                              "start over (mpirun also stops the other ranks this way when one rank fails: then "
                              "that rank's message says why)\n",
                              rank);
  start_up_message_length = n > 0 && n < static_cast<int>(sizeof start_up_message) ? n : 0;
  installHandler(stopDuringStartUp);
}

void installStopSignalHandlers() { installHandler(raiseFlag); }

void silenceStartUpSignalMessage() { start_up_message_length = 0; }

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
