// LIGGGHTS ends the process on an error in the case's script: an error found on every rank (Error::all)
// with MPI_Finalize and exit(1), one found by a single rank (Error::one) with MPI_Abort(world, 1). Its
// Error class has no virtual hook. While a ScriptErrorReport lives, either end prints a parcelflow line
// saying that the LIGGGHTS ERROR above came from the case's script (with the liggghts.variables it got)
// and ends with exit code 2, a user error like every other.
#pragma once

#include <string>

namespace parcelflow::coupling {

class ScriptErrorReport {
 public:
  // `note` is printed by `rank` 0 after Error::all, by the aborting rank after Error::one
  ScriptErrorReport(std::string note, int rank);
  ~ScriptErrorReport();
  ScriptErrorReport(const ScriptErrorReport&) = delete;
  ScriptErrorReport& operator=(const ScriptErrorReport&) = delete;
};

}  // namespace parcelflow::coupling
