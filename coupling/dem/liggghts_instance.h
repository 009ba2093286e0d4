// Owns one in-process LIGGGHTS instance on its own duplicate of a communicator, with parcelflow's
// styles registered (see liggghts_post_create_hook.cpp). For `parcelflow dem` it installs LIGGGHTS' own
// signal handlers, so that Ctrl-C or a scheduler's SIGTERM stops it the way the stock `liggghts` binary does
// (a coupled run owns those signals itself: run/stop_signal.h).
#pragma once

#include <mpi.h>

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS { class LAMMPS; }

namespace parcelflow::coupling {

class LiggghtsInstance {
 public:
  // `arguments` are LIGGGHTS command-line arguments (without the program name), e.g. {"-in", "x.in"}.
  LiggghtsInstance(MPI_Comm world, const std::vector<std::string>& arguments);
  ~LiggghtsInstance();
  LiggghtsInstance(const LiggghtsInstance&) = delete;
  LiggghtsInstance& operator=(const LiggghtsInstance&) = delete;

  LAMMPS_NS::LAMMPS* lammps() const { return lmp_; }
  void runInputFile();                 // the file given with -in, as `liggghts -in FILE` does
  void runFile(const std::string& path);
  void command(const std::string& line);
  // Runs `line` with LIGGGHTS' screen output filtered: only lines holding ERROR or WARNING reach the
  // terminal (the log file gets everything). The coupled loop's short DEM runs would otherwise print a
  // thermo header and rows for every coupling step.
  void quietCommand(const std::string& line);

  static void installSignalHandlers();

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  LAMMPS_NS::LAMMPS* lmp_ = nullptr;
  std::FILE* filtered_screen_ = nullptr;
};

}  // namespace parcelflow::coupling
