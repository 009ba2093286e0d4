#pragma once
// The pressure preconditioner kept over several gas steps. The PISO pressure matrix changes little
// from one gas step to the next (gas fraction and drag move slowly), and PCG with the preconditioner
// of a nearby matrix converges to the same tolerance; only its iteration count depends on the fit.
// A stale preconditioner costs iterations, a new one its build (BoomerAMG's setup, a factorisation),
// so it is rebuilt when
//   - it has served `maxSteps` gas steps (solver.pressure.preconditioner_reuse; 1 = every step), or
//   - the iterations it cost beyond those of its own build step, summed over the solves since then
//     (each solve against the same solve of the build step), reach what a build costs in iterations
//     (setupCostInIterations): rent until the rent paid equals the price of buying. With iterations
//     growing linearly in the steps since the build, this is the interval of least total cost.
// Iteration counts are the same on all ranks (global dot products), so all ranks rebuild together,
// as the collective build requires, and a run stays reproducible.
#include <memory>
#include <vector>

#include "cfd/linear/linear_solver_settings.hpp"
#include "cfd/linear/ldu_matrix.hpp"
#include "cfd/linear/preconditioner.hpp"

namespace parcelflow::cfd {

class ReusedPreconditioner {
 public:
  ReusedPreconditioner(PreconditionerType type, int maxSteps);

  // The preconditioner for this step's matrix: the kept one, or one newly built from `matrix`.
  std::shared_ptr<const Preconditioner> forStep(const LduMatrix& matrix);
  // The PCG iterations of this step's next solve with it (call once per solve, in a fixed order).
  void recordIterations(int iterations);
  // The next forStep builds a new one.
  void rebuildNextStep() { precond_.reset(); }
  // Whether the last forStep built a new one.
  bool builtThisStep() const { return age_ == 1; }

 private:
  PreconditionerType type_;
  int maxSteps_;
  std::shared_ptr<const Preconditioner> precond_;
  int age_ = 0;                        // steps served, including this one
  std::vector<int> freshIterations_;   // per solve of the build step
  std::size_t solve_ = 0;              // this step's solves so far
  long excessIterations_ = 0;          // beyond freshIterations_, summed since the build
};

}  // namespace parcelflow::cfd
