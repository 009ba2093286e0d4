// parcelflow owns SIGTERM and SIGINT in a coupled run (LIGGGHTS' own handlers would write restart files into
// the case folder and run on). The handler only raises a flag on the rank that got the signal; the loop
// agrees on it across ranks once per coupling step (stopRequested), writes a checkpoint and stops.
#pragma once

#include <mpi.h>

namespace parcelflow::coupling {

// Before the coupled loop (LIGGGHTS' filling and settling can take minutes) there is nothing to checkpoint:
// a signal ends the rank that got it at once, with a line saying so and exit code 128 + signal (mpirun then
// ends the others). Without this, the default action ended the job with code 1 and no word.
void installStartUpSignalHandlers(int rank);
void installStopSignalHandlers();
// Once this rank has reported why the run ends, a signal during start-up (mpirun stopping the ranks after one
// of them exited) ends it without the start-up line, which would point away from the reason.
void silenceStartUpSignalMessage();
// The signal any rank got (0: none). Collective: one all-reduce of one int.
int stopRequested(MPI_Comm comm);

// Seconds Open MPI's mpirun waits after forwarding a signal before it kills the ranks
// (odls_base_sigkill_timeout, default 1 s; its MCA settings reach the ranks as OMPI_MCA_* variables); a
// negative value when the ranks were not started by Open MPI's mpirun.
double mpirunKillDelay();

}  // namespace parcelflow::coupling
