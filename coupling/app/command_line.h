// The parcelflow command line: `parcelflow run CASE [--output DIR] [--end SECONDS] [--restart CHECKPOINT]`, `parcelflow dem SCRIPT
// [-var NAME VALUE]... [-log FILE]`, `--help`, `--version`.
// Parsing is separate from running so that every malformed line is rejected (exit code 2) before MPI
// work or LIGGGHTS starts, and so that it can be unit-tested.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace parcelflow::coupling {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct CommandLine {
  enum class Action { help, version, dem, run };
  Action action = Action::help;
  std::string script;                                      // dem: the LIGGGHTS input script
  std::vector<std::pair<std::string, std::string>> vars;   // dem: -var NAME VALUE, in order
  std::string log_file;                                    // dem: -log FILE (LIGGGHTS' default if empty)
  std::string case_folder;                                 // run: the case folder
  std::string output_folder;                               // run: --output DIR (default CASE/output)
  double end_time = 0.0;                                   // run: --end SECONDS (0: time.end of case.yaml)
  std::string restart;                                     // run: --restart CHECKPOINT (a checkpoint folder)
};

// Throws UsageError naming the offending argument and what is allowed.
CommandLine parseCommandLine(const std::vector<std::string>& args);

std::string usageText();

}  // namespace parcelflow::coupling
