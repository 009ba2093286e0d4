#pragma once
// Ghost-cell communication of one rank: forward `exchange` copies owned values to the ghost copies on
// other ranks; `reverseAdd` sums ghost contributions (e.g. deposited particle volume) into the owners
// and zeroes the ghosts. Local cells are ordered owned first, then ghosts.
#include <mpi.h>

#include <vector>

#include "types.hpp"

namespace parcelflow::cfd {

class Halo {
 public:
  struct Neighbour {
    int rank = -1;
    std::vector<int> send;  // owned local cells that are ghosts on `rank`, in its ghost order
    std::vector<int> recv;  // local ghost cells owned by `rank`
  };

  Halo() = default;
  Halo(MPI_Comm comm, int nOwned, int nLocal, std::vector<Neighbour> neighbours);

  void exchange(ScalarField& field) const { exchangeRaw(field.data(), 1, field.size()); }
  void exchange(VectorField& field) const { exchangeRaw(field[0].data(), 3, field.size()); }
  void reverseAdd(ScalarField& field) const { reverseAddRaw(field.data(), 1, field.size()); }
  void reverseAdd(VectorField& field) const { reverseAddRaw(field[0].data(), 3, field.size()); }

  const std::vector<Neighbour>& neighbours() const { return neighbours_; }

 private:
  void exchangeRaw(double* data, int width, std::size_t size) const;
  void reverseAddRaw(double* data, int width, std::size_t size) const;
  void checkSize(std::size_t size) const;
  MPI_Comm comm_ = MPI_COMM_NULL;
  int nOwned_ = 0;
  int nLocal_ = 0;
  std::vector<Neighbour> neighbours_;
};

}  // namespace parcelflow::cfd
