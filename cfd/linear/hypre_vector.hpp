#pragma once
// A hypre ParVector over the owned rows of a HypreMatrix, filled from and copied back to the owned
// entries of a ScalarField.
#include <HYPRE_IJ_mv.h>
#include <HYPRE_parcsr_mv.h>

#include <memory>
#include <type_traits>
#include <vector>

#include "cfd/linear/hypre_matrix.hpp"

namespace parcelflow::cfd {

class HypreVector {
 public:
  explicit HypreVector(const HypreMatrix& matrix);  // collective

  HYPRE_ParVector par() const { return par_; }
  void set(const ScalarField& owned);
  void get(ScalarField& owned) const;
  void setZero();

 private:
  std::vector<HYPRE_BigInt> rows_;
  std::unique_ptr<std::remove_pointer_t<HYPRE_IJVector>, decltype(&HYPRE_IJVectorDestroy)> ij_{
      nullptr, &HYPRE_IJVectorDestroy};
  HYPRE_ParVector par_ = nullptr;  // owned by ij_
};

}  // namespace parcelflow::cfd
