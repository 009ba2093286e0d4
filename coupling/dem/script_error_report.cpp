#include "coupling/dem/script_error_report.h"

#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <utility>

namespace parcelflow::coupling {

namespace {

bool script_running = false;
int script_rank = 0;
std::string script_note;

// Error::all: LIGGGHTS' exit(1) runs the exit handlers
void reportAtExit() {
  if (!script_running) return;
  if (script_rank == 0) std::fputs(script_note.c_str(), stderr);
  std::fflush(nullptr);
  std::_Exit(2);
}

}  // namespace

ScriptErrorReport::ScriptErrorReport(std::string note, int rank) {
  static const bool handler_installed = std::atexit(reportAtExit) == 0;
  (void)handler_installed;
  script_note = std::move(note);
  script_rank = rank;
  script_running = true;
}

ScriptErrorReport::~ScriptErrorReport() { script_running = false; }

}  // namespace parcelflow::coupling

// Error::one: MPI_Abort runs no exit handler. This definition takes the place of the MPI library's for
// every caller in the process, libliggghts.so included (the MPI standard's profiling interface: the
// library's own entry point stays reachable as PMPI_Abort). Outside the case's script it only passes on.
extern "C" int MPI_Abort(MPI_Comm comm, int errorcode) {
  using namespace parcelflow::coupling;
  if (script_running) {
    std::fputs(script_note.c_str(), stderr);
    std::fflush(nullptr);
    errorcode = 2;
  }
  return PMPI_Abort(comm, errorcode);
}
