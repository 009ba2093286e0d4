// The parcelflow program. `parcelflow run CASE` runs a coupled case; `parcelflow dem SCRIPT` runs a
// LIGGGHTS script in-process exactly as the stock `liggghts -in SCRIPT` does, with parcelflow's parcel
// styles available.
#include <mpi.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "cfd/config_error.hpp"
#include "command_line.h"
#include "coupled_run.h"
#include "liggghts_instance.h"
#include "version.h"

namespace pc = parcelflow::coupling;

namespace {

int runDem(const pc::CommandLine& cl) {
  std::vector<std::string> arguments = {"-in", cl.script};
  for (const auto& [name, value] : cl.vars) arguments.insert(arguments.end(), {"-var", name, value});
  if (!cl.log_file.empty()) arguments.insert(arguments.end(), {"-log", cl.log_file});
  pc::LiggghtsInstance dem(MPI_COMM_WORLD, arguments);
  dem.runInputFile();
  return 0;
}

// Case errors (cfd::ConfigError) are found by every rank alike, before any work: rank 0 reports.
int runCase(const pc::CommandLine& cl) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  try {
    pc::CoupledRun run({cl.case_folder, cl.output_folder, cl.end_time});
    run.initialize();
    while (run.advance()) {
    }
    run.finalize();
  } catch (const parcelflow::cfd::ConfigError& e) {
    if (rank == 0) std::cerr << "parcelflow: error in case '" << cl.case_folder << "': " << e.what() << "\n";
    return 2;
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
    std::cerr << "parcelflow: " << e.what() << "\n\n" << pc::usageText();
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
    std::cerr << "parcelflow: cannot read the LIGGGHTS script '" << cl.script << "'\n";
    return 2;
  }

  pc::LiggghtsInstance::installSignalHandlers();
  MPI_Init(&argc, &argv);
  const int status = cl.action == pc::CommandLine::Action::run ? runCase(cl) : runDem(cl);
  MPI_Finalize();
  return status;
}
