// BoomerAMG (hypre) as the pressure preconditioner: on a pressure-like Poisson problem (face
// coefficients jumping between a dense bed and the freeboard, a fixed-pressure outlet on top) the
// AMG-preconditioned PCG reaches the block_ic solution on any number of ranks in far fewer
// iterations; a non-converged solve is reported; a hypre error return becomes an InternalError.
#include <HYPRE_IJ_mv.h>
#include <gtest/gtest.h>
#include <mpi.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "cfd/base/config_error.hpp"
#include "cfd/solver/gas_config.hpp"
#include "cfd/linear/hypre_library.hpp"
#include "cfd/base/internal_error.hpp"
#include "cfd/linear/krylov_solver.hpp"
#include "tests/unit/cfd/pressure_problem.hpp"

using namespace parcelflow::cfd;

namespace {
SolveStats solve(const PressureProblem& p, PreconditionerType type, ScalarField& x,
                 double tolerance = 1e-13, int maxIterations = 5000) {
  x.assign(p.A.mesh().nLocalCells(), 0.0);
  return KrylovSolver(p.A, {tolerance, 1e-300, maxIterations, type}).pcg(x, p.b);
}
}  // namespace

TEST(BoomerAmg, MatchesBlockIcWithFarFewerIterations) {
  const Mesh m = bedMesh();
  const PressureProblem p(m);
  ScalarField xIc, xAmg;
  const SolveStats ic = solve(p, PreconditionerType::BlockIncompleteCholesky, xIc);
  const SolveStats amg = solve(p, PreconditionerType::BoomerAmg, xAmg);
  ASSERT_TRUE(ic.converged);
  ASSERT_TRUE(amg.converged);
  double diff = 0.0, scale = 0.0;
  for (int c = 0; c < m.nOwnedCells(); ++c) {
    diff = std::max(diff, std::abs(xAmg[c] - xIc[c]));
    scale = std::max(scale, std::abs(xIc[c]));
  }
  diff = m.max(diff);
  scale = m.max(scale);
  if (m.rank() == 0)
    std::printf("[measured] %d ranks: PCG iterations block_ic %d, boomeramg %d; "
                "max |dx| / max |x| %.2e\n",
                m.nRanks(), ic.iterations, amg.iterations, diff / scale);
  EXPECT_LT(diff, 1e-10 * scale);
  EXPECT_LT(5 * amg.iterations, ic.iterations);
}

TEST(BoomerAmg, UnconvergedSolveIsReported) {
  const Mesh m = bedMesh();
  const PressureProblem p(m);
  ScalarField x;
  const SolveStats stats = solve(p, PreconditionerType::BoomerAmg, x, 1e-13, 2);
  EXPECT_FALSE(stats.converged);
  EXPECT_EQ(stats.iterations, 2);
}

TEST(BoomerAmg, HypreErrorBecomesInternalErrorAndIsCleared) {
  const HYPRE_BigInt row = 0;
  const double value = 1.0;
  try {
    PARCELFLOW_HYPRE_CALL(HYPRE_IJVectorSetValues(nullptr, 1, &row, &value));
    FAIL() << "a null hypre vector was accepted";
  } catch (const InternalError& e) {
    EXPECT_NE(std::string(e.what()).find("HYPRE_IJVectorSetValues"), std::string::npos) << e.what();
  }
  // hypre's error flag is sticky; after the exception the next solve must work.
  const Mesh m = bedMesh();
  const PressureProblem p(m);
  ScalarField x;
  EXPECT_TRUE(solve(p, PreconditionerType::BoomerAmg, x).converged);
}

TEST(BoomerAmg, PressureDefaultBlockIcStillSelectableMomentumRefuses) {
  const std::string base = kSmallGasCase;
  EXPECT_EQ(GasConfig(YAML::Load(base)).settings().solver.pressure.preconditioner,
            PreconditionerType::BoomerAmg);
  const GasConfig blockIc(YAML::Load(base + "solver: {pressure: {preconditioner: block_ic}}"));
  EXPECT_EQ(blockIc.settings().solver.pressure.preconditioner,
            PreconditionerType::BlockIncompleteCholesky);
  EXPECT_THROW(GasConfig(YAML::Load(base + "solver: {momentum: {preconditioner: boomeramg}}")),
               ConfigError);
}
