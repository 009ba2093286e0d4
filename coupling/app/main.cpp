// The parcelflow program. `parcelflow run CASE` runs a coupled case; `parcelflow dem SCRIPT` runs a
// LIGGGHTS script in-process exactly as the stock `liggghts -in SCRIPT` does, with parcelflow's parcel
// styles available.
#include <mpi.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "cfd/base/config_error.hpp"
#include "cfd/base/internal_error.hpp"
#include "cfd/io/mpi_io_defaults.hpp"
#include "coupling/run/blowup_guard.h"
#include "coupling/app/command_line.h"
#include "coupling/dem/contact_time_check.h"
#include "coupling/run/coupled_run.h"
#include "coupling/dem/liggghts_instance.h"
#include "coupling/run/stop_signal.h"
#include "version.h"

namespace pc = parcelflow::coupling;

namespace {

// Through mpirun a rank's stdout and stderr reach the terminal by separate pipes, and every `<<` on the
// unbuffered std::cerr is a write of its own: a message written in pieces can be cut by a line of stdout
// (a test once read "stopped by signal parcelflow: checkpoint ... 15 after a checkpoint"). One write keeps
// each message whole.
void printToStderr(const std::string& text) { std::fwrite(text.data(), 1, text.size(), stderr); }

int runDem(const pc::CommandLine& cl) {
  std::vector<std::string> arguments = {"-in", cl.script};
  for (const auto& [name, value] : cl.vars) arguments.insert(arguments.end(), {"-var", name, value});
  if (!cl.log_file.empty()) arguments.insert(arguments.end(), {"-log", cl.log_file});
  pc::LiggghtsInstance dem(MPI_COMM_WORLD, arguments);
  try {
    dem.runInputFile();
  } catch (const parcelflow::plugins::DemStepTooLong& e) {  // fix parcel/implicit_drag, on every rank
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    const auto error = pc::demStepError("timestep", e.estimate, e.dem_step,
                                        "at the start of the run at step " + std::to_string(e.step));
    if (rank == 0) printToStderr("parcelflow: error in script '" + cl.script + "': " + error.what() + "\n");
    return 2;
  }
  return 0;
}

// User errors (cfd::ConfigError) are found by every rank alike, before any work: rank 0 reports them and
// the run exits with code 2; a diverged run (run/blowup_guard.h), found by all ranks alike, exits with 3.
// An internal error is a bug: the rank that found it says so and stops all ranks.
// Any other failure (a file that cannot be written) stops all ranks with its message.
int runCase(const pc::CommandLine& cl) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  try {
    pc::CoupledRun run({cl.case_folder, cl.output_folder, cl.end_time, cl.restart});
    run.initialize();
    while (run.advance()) {
    }
    if (run.stopSignal()) {
      if (rank == 0)
        printToStderr("parcelflow: stopped by signal " + std::to_string(run.stopSignal()) +
                      " after a checkpoint; continue with\n  mpirun -np " + std::to_string(ranks) +
                      " parcelflow run " + cl.case_folder +
                      (cl.output_folder.empty() ? "" : " --output " + cl.output_folder) + " --restart " +
                      run.lastCheckpoint() + "\n");
      return 128 + run.stopSignal();
    }
    run.finalize();
  } catch (const parcelflow::cfd::ConfigError& e) {
    pc::silenceStartUpSignalMessage();
    if (rank == 0) printToStderr("parcelflow: error in case '" + cl.case_folder + "': " + e.what() + "\n");
    return 2;
  } catch (const pc::DivergedError& e) {
    pc::silenceStartUpSignalMessage();
    if (rank == 0) printToStderr(std::string("parcelflow: error: ") + e.what() + "\n");
    return 3;
  } catch (const parcelflow::cfd::InternalError& e) {
    pc::silenceStartUpSignalMessage();
    printToStderr("parcelflow: rank " + std::to_string(rank) + ": " + e.what() +
                  "\nparcelflow: this is a bug in parcelflow, not in your case; please report it with the case\n");
    MPI_Abort(MPI_COMM_WORLD, 70);
  } catch (const std::exception& e) {
    pc::silenceStartUpSignalMessage();
    printToStderr("parcelflow: rank " + std::to_string(rank) + ": " + e.what() + "\n");
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // LIGGGHTS ends the process on an input error (exit or MPI_Abort): line buffering makes sure the
  // user sees every line printed before that.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);

  pc::CommandLine cl;
  try {
    cl = pc::parseCommandLine(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const pc::UsageError& e) {
    printToStderr(std::string("parcelflow: ") + e.what() + "\n\n" + pc::usageText());
    return 2;
  }
  if (cl.action == pc::CommandLine::Action::help) {
    std::cout << pc::usageText();
    return 0;
  }
  if (cl.action == pc::CommandLine::Action::version) {
    std::cout << "parcelflow " << PARCELFLOW_VERSION << " (LIGGGHTS 3.8.0 in-process)\n";
    return 0;
  }
  if (cl.action == pc::CommandLine::Action::dem && !std::ifstream(cl.script)) {
    printToStderr("parcelflow: cannot read the LIGGGHTS script '" + cl.script + "'\n");
    return 2;
  }

  // `parcelflow dem` stops on a signal as the stock `liggghts` binary does; a coupled run installs its own
  // handlers (run/stop_signal.h).
  if (cl.action == pc::CommandLine::Action::dem) pc::LiggghtsInstance::installSignalHandlers();
  parcelflow::cfd::preferRomioForMpiIo();
  MPI_Init(&argc, &argv);
  const int status = cl.action == pc::CommandLine::Action::run ? runCase(cl) : runDem(cl);
  MPI_Finalize();
  return status;
}
