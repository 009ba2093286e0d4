#include "coupling/app/command_line.h"

#include <cmath>
#include <set>

namespace parcelflow::coupling {

namespace {

CommandLine parseDem(const std::vector<std::string>& args) {
  CommandLine cl;
  cl.action = CommandLine::Action::dem;
  if (args.size() < 2 || args[1].empty() || args[1][0] == '-')
    throw UsageError("'parcelflow dem' needs a LIGGGHTS input script: parcelflow dem SCRIPT");
  cl.script = args[1];
  for (std::size_t i = 2; i < args.size();) {
    const std::string& opt = args[i];
    if (opt == "-var" || opt == "-v") {
      if (i + 2 >= args.size())
        throw UsageError("option '" + opt + "' needs a name and a value: -var NAME VALUE");
      cl.vars.emplace_back(args[i + 1], args[i + 2]);
      i += 3;
    } else if (opt == "-log") {
      if (i + 1 >= args.size()) throw UsageError("option '-log' needs a file name: -log FILE");
      cl.log_file = args[i + 1];
      i += 2;
    } else {
      throw UsageError("unknown option '" + opt + "' for 'parcelflow dem'; allowed: -var NAME VALUE, -log FILE");
    }
  }
  return cl;
}

double parseEndTime(const std::string& text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(value > 0.0) || !std::isfinite(value))
    throw UsageError("option '--end' got '" + text + "'; allowed: a simulated end time in seconds, > 0");
  return value;
}

CommandLine parseRun(const std::vector<std::string>& args) {
  CommandLine cl;
  cl.action = CommandLine::Action::run;
  if (args.size() < 2 || args[1].empty() || args[1][0] == '-')
    throw UsageError("'parcelflow run' needs a case folder: parcelflow run CASE [--output DIR] [--end SECONDS] "
                     "[--restart CHECKPOINT]");
  cl.case_folder = args[1];
  std::set<std::string> given;
  for (std::size_t i = 2; i < args.size(); i += 2) {
    const std::string& opt = args[i];
    if (!given.insert(opt).second)  // one value would win silently
      throw UsageError("option '" + opt + "' is given twice; allowed: each option once");
    if (opt == "--output") {
      if (i + 1 >= args.size() || args[i + 1].empty())
        throw UsageError("option '--output' needs a folder: --output DIR (a non-empty path)");
      cl.output_folder = args[i + 1];
    } else if (opt == "--end") {
      if (i + 1 >= args.size()) throw UsageError("option '--end' needs a time: --end SECONDS");
      cl.end_time = parseEndTime(args[i + 1]);
    } else if (opt == "--restart") {
      if (i + 1 >= args.size()) throw UsageError("option '--restart' needs a checkpoint folder: --restart CHECKPOINT");
      cl.restart = args[i + 1];
    } else {
      throw UsageError("unknown option '" + opt +
                       "' for 'parcelflow run'; allowed: --output DIR, --end SECONDS, --restart CHECKPOINT");
    }
  }
  return cl;
}

}  // namespace

CommandLine parseCommandLine(const std::vector<std::string>& args) {
  if (args.empty()) throw UsageError("no command given");
  const std::string& command = args[0];
  if (command == "--help" || command == "-h" || command == "help") {
    if (args.size() > 1) throw UsageError("'" + command + "' takes no arguments");
    return CommandLine{};
  }
  if (command == "--version") {
    if (args.size() > 1) throw UsageError("'--version' takes no arguments");
    CommandLine cl;
    cl.action = CommandLine::Action::version;
    return cl;
  }
  if (command == "dem") return parseDem(args);
  if (command == "run") return parseRun(args);
  throw UsageError("unknown command '" + command + "'; allowed: run, dem, --help, --version");
}

std::string usageText() {
  return "usage: parcelflow run CASE [--output DIR] [--end SECONDS] [--restart CHECKPOINT]\n"
         "       parcelflow dem SCRIPT [-var NAME VALUE]... [-log FILE]\n"
         "       parcelflow --help | --version\n"
         "\n"
         "  run CASE     run the coupled CFD-DEM case in folder CASE (case.yaml + its LIGGGHTS script);\n"
         "               mpirun -np N parcelflow run CASE for N ranks. Output goes to DIR, by default\n"
         "               CASE/<output.folder of case.yaml>: monitors.csv, log.liggghts, fields.\n"
         "               --end SECONDS replaces time.end of case.yaml (a shorter or longer run).\n"
         "               --restart CHECKPOINT continues a run from a checkpoint folder\n"
         "               (DIR/checkpoints/step_<N>, written at output.checkpoint_interval and when\n"
         "               SIGTERM or SIGINT stops a run).\n"
         "  dem SCRIPT   run a LIGGGHTS input script in-process with parcelflow's parcel styles\n"
         "               registered (any number of MPI ranks: mpirun -np N parcelflow dem SCRIPT).\n"
         "               -var NAME VALUE defines a LIGGGHTS index variable, as for `liggghts -var`;\n"
         "               -log FILE moves LIGGGHTS' log (default log.liggghts in the current folder).\n";
}

}  // namespace parcelflow::coupling
