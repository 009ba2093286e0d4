#include "cfd/linear/hypre_vector.hpp"

#include <HYPRE.h>

#include "cfd/linear/hypre_library.hpp"

namespace parcelflow::cfd {

HypreVector::HypreVector(const HypreMatrix& matrix) : rows_(matrix.nOwnedRows()) {
  for (int i = 0; i < matrix.nOwnedRows(); ++i) rows_[i] = matrix.firstRow() + i;
  HYPRE_IJVector ij = nullptr;
  PARCELFLOW_HYPRE_CALL(HYPRE_IJVectorCreate(matrix.comm(), matrix.firstRow(),
                                             matrix.firstRow() + matrix.nOwnedRows() - 1, &ij));
  ij_.reset(ij);
  PARCELFLOW_HYPRE_CALL(HYPRE_IJVectorSetObjectType(ij, HYPRE_PARCSR));
  PARCELFLOW_HYPRE_CALL(HYPRE_IJVectorInitialize(ij));
  PARCELFLOW_HYPRE_CALL(HYPRE_IJVectorAssemble(ij));
  void* object = nullptr;
  PARCELFLOW_HYPRE_CALL(HYPRE_IJVectorGetObject(ij, &object));
  par_ = static_cast<HYPRE_ParVector>(object);
}

// Rows are all owned here, so Set/GetValues after assembly write and read the local part directly
// (no communication, no re-assembly).
void HypreVector::set(const ScalarField& owned) {
  PARCELFLOW_HYPRE_CALL(HYPRE_IJVectorSetValues(ij_.get(), static_cast<HYPRE_Int>(rows_.size()),
                                                rows_.data(), owned.data()));
}

void HypreVector::get(ScalarField& owned) const {
  PARCELFLOW_HYPRE_CALL(HYPRE_IJVectorGetValues(ij_.get(), static_cast<HYPRE_Int>(rows_.size()),
                                                rows_.data(), owned.data()));
}

void HypreVector::setZero() { PARCELFLOW_HYPRE_CALL(HYPRE_ParVectorSetConstantValues(par_, 0.0)); }

}  // namespace parcelflow::cfd
