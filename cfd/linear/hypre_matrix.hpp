#pragma once
// An LduMatrix (plus an optional extra diagonal) copied into a hypre ParCSR matrix. hypre wants every
// rank to own one contiguous range of global rows, which the mesh's global cell ids (ordered like the
// background) are not; so rank r numbers its owned cells from the sum of the owned-cell counts of
// ranks 0..r-1, and the ghosts learn their owner's row through the halo exchange.
#include <HYPRE_IJ_mv.h>
#include <HYPRE_parcsr_mv.h>

#include <memory>
#include <type_traits>

#include "cfd/linear/ldu_matrix.hpp"

namespace parcelflow::cfd {

class HypreMatrix {
 public:
  // Collective over the mesh's communicator.
  HypreMatrix(const LduMatrix& matrix, const ScalarField& extraDiag);

  HYPRE_ParCSRMatrix parcsr() const { return parcsr_; }
  MPI_Comm comm() const { return comm_; }
  // The global rows of this rank's owned cells: firstRow() + local cell index.
  HYPRE_BigInt firstRow() const { return firstRow_; }
  int nOwnedRows() const { return nOwned_; }

 private:
  MPI_Comm comm_;
  int nOwned_;
  HYPRE_BigInt firstRow_ = 0;
  std::unique_ptr<std::remove_pointer_t<HYPRE_IJMatrix>, decltype(&HYPRE_IJMatrixDestroy)> ij_{
      nullptr, &HYPRE_IJMatrixDestroy};
  HYPRE_ParCSRMatrix parcsr_ = nullptr;  // owned by ij_
};

}  // namespace parcelflow::cfd
