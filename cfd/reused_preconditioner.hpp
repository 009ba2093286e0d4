#pragma once
// The pressure preconditioner kept over several gas steps. The PISO pressure matrix changes little
// from one gas step to the next (gas fraction and drag move slowly), and PCG with the preconditioner
// of a nearby matrix converges to the same tolerance; only its iteration count depends on the fit.
// Building it (BoomerAMG's setup, a block Cholesky factorisation) is the larger part of a pressure
// solve on small meshes, so it is rebuilt only when
//   - it has served `maxSteps` gas steps (solver.pressure.preconditioner_reuse; 1 = every step), or
//   - the first solve of a step needed more than twice the iterations of the first solve after the
//     last build, plus 2: the matrix has moved away from the one it was built for.
// Iteration counts are the same on all ranks (global dot products), so all ranks rebuild together,
// as the collective build requires, and a run stays reproducible.
#include <memory>

#include "gas_settings.hpp"
#include "ldu_matrix.hpp"
#include "preconditioner.hpp"

namespace parcelflow::cfd {

class ReusedPreconditioner {
 public:
  ReusedPreconditioner(PreconditionerType type, int maxSteps);

  // The preconditioner for this step's matrix: the kept one, or one newly built from `matrix`.
  std::shared_ptr<const Preconditioner> forStep(const LduMatrix& matrix);
  // The PCG iterations of this step's first solve with it.
  void recordIterations(int iterations);
  // The next forStep builds a new one.
  void rebuildNextStep() { precond_.reset(); }
  // Whether the last forStep built a new one.
  bool builtThisStep() const { return age_ == 1; }

 private:
  PreconditionerType type_;
  int maxSteps_;
  std::shared_ptr<const Preconditioner> precond_;
  int age_ = 0;               // steps served, including this one
  int freshIterations_ = -1;  // first solve after the last build; -1 until recorded
  bool outgrown_ = false;
};

}  // namespace parcelflow::cfd
