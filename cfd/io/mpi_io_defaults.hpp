#pragma once
// Call before MPI_Init. Open MPI's OMPIO layer (its default MPI-IO) opens every file through the sharedfp
// "sm" component, which guards it with a named POSIX semaphore keyed by the file's base name only
// (/dev/shm/sem.OMPIO_<name>). A process killed while holding it (SIGKILL, out of memory) leaves it taken,
// and every later job on the machine that opens a file of that name (each checkpoint's gas.h5.partial)
// waits forever in MPI_File_open. ROMIO (Open MPI 4's component romio321, Debian 12) has no such state, so
// it is the default here; a user's own OMPI_MCA_io setting wins. Other MPI libraries ignore the variable.
#include <cstdlib>

namespace parcelflow::cfd {

inline void preferRomioForMpiIo() { setenv("OMPI_MCA_io", "romio321", /*overwrite=*/0); }

}  // namespace parcelflow::cfd
