#pragma once
// The process-wide part of using hypre: its one-time initialisation and the conversion of its error
// codes. hypre reports errors only through return codes and a sticky global flag; every call goes
// through PARCELFLOW_HYPRE_CALL so that a failure stops the solve with an InternalError naming the
// call, instead of iterating on garbage.
#include <HYPRE_utilities.h>

namespace parcelflow::cfd {

// Calls HYPRE_Init the first time (after MPI_Init). hypre's handle then lives until the process
// ends: HYPRE_Finalize would have to run after the last hypre object of any solver is destroyed.
void initialiseHypreOnce();

// Throws InternalError naming `call` when code != 0, and clears hypre's sticky error flag first so
// that later, unrelated calls do not report the same failure again.
void checkHypre(HYPRE_Int code, const char* call, const char* file, int line);

}  // namespace parcelflow::cfd

#define PARCELFLOW_HYPRE_CALL(expr) ::parcelflow::cfd::checkHypre((expr), #expr, __FILE__, __LINE__)
