#pragma once
// Ghost-cell communication of one rank: `exchange` copies owned values to their ghost copies on the
// other ranks. Local cells are ordered owned first, then ghosts.
#include <mpi.h>

#include <vector>

#include "cfd/base/types.hpp"

namespace parcelflow::cfd {

class Halo {
 public:
  struct Neighbour {
    int rank = -1;
    std::vector<int> send;  // owned local cells that are ghosts on `rank`, in its ghost order
    std::vector<int> recv;  // local ghost cells owned by `rank`
  };

  Halo() = default;
  Halo(MPI_Comm comm, int nLocal, std::vector<Neighbour> neighbours);

  void exchange(ScalarField& field) const { exchangeRaw(field.data(), 1, field.size()); }
  void exchange(VectorField& field) const { exchangeRaw(field[0].data(), 3, field.size()); }

 private:
  void exchangeRaw(double* data, int width, std::size_t size) const;
  void checkSize(std::size_t size) const;
  MPI_Comm comm_ = MPI_COMM_NULL;
  int nLocal_ = 0;
  std::vector<Neighbour> neighbours_;
};

}  // namespace parcelflow::cfd
