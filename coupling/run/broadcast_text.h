// A text known on one rank (a checkpoint id, an error found by the rank that writes a file) sent to all, so
// that every rank acts on it alike. Collective.
#pragma once

#include <mpi.h>

#include <string>

namespace parcelflow::coupling {

inline std::string broadcastText(std::string text, int root, MPI_Comm comm) {
  int size = static_cast<int>(text.size());
  MPI_Bcast(&size, 1, MPI_INT, root, comm);
  text.resize(size);
  MPI_Bcast(text.data(), size, MPI_CHAR, root, comm);
  return text;
}

}  // namespace parcelflow::coupling
