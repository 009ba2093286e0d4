// run_dem_script SCRIPT: runs a LIGGGHTS script in-process with parcelflow's styles registered, screen
// output on stdout. The error tests run it on scripts that must stop with a given message.
#include <mpi.h>

#include <cstdio>

#include "input.h"
#include "lammps.h"
#include "liggghts_plugins/register_styles.h"

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  setvbuf(stdout, nullptr, _IOLBF, 0);
  if (argc != 2) {
    std::fprintf(stderr, "usage: run_dem_script SCRIPT\n");
    MPI_Abort(MPI_COMM_WORLD, 2);
  }
  const char* args[] = {"liggghts", "-log", "none", "-echo", "none"};
  auto* lmp = new LAMMPS_NS::LAMMPS(5, const_cast<char**>(args), MPI_COMM_WORLD);
  parcelflow::plugins::register_styles(lmp);
  lmp->input->file(argv[1]);
  delete lmp;
  MPI_Finalize();
  return 0;
}
