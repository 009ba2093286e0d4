// The pressure preconditioner kept over gas steps: PCG with the preconditioner of a nearby matrix (the
// bed's pattern moved) reaches the same solution as with a fresh one, for block_cholesky and boomeramg
// on any number of ranks; the preconditioner is rebuilt after preconditioner_reuse steps or when the
// iterations it cost beyond its build step's add up to a build's cost; the key is read for the pressure
// solver only.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cfd/base/config_error.hpp"
#include "cfd/solver/gas_config.hpp"
#include "cfd/linear/krylov_solver.hpp"
#include "cfd/linear/reused_preconditioner.hpp"
#include "tests/unit/cfd/pressure_problem.hpp"

using namespace parcelflow::cfd;

namespace {
const LinearSolverSettings kTight{1e-12, 1e-300, 5000, PreconditionerType::BoomerAmg};

double maxRelativeDifference(const Mesh& m, const ScalarField& x, const ScalarField& reference) {
  double diff = 0.0, scale = 0.0;
  for (int c = 0; c < m.nOwnedCells(); ++c) {
    diff = std::max(diff, std::abs(x[c] - reference[c]));
    scale = std::max(scale, std::abs(reference[c]));
  }
  return m.max(diff) / m.max(scale);
}

// Runs one step per entry of `solvesPerStep` (the PCG iterations of each of its solves) and returns
// which steps built the preconditioner: 'B' built, '.' kept.
std::string buildPattern(PreconditionerType type, int maxSteps, const LduMatrix& A,
                         const std::vector<std::vector<int>>& solvesPerStep) {
  ReusedPreconditioner reused(type, maxSteps);
  std::string built;
  for (const auto& solves : solvesPerStep) {
    reused.forStep(A);
    built += reused.builtThisStep() ? 'B' : '.';
    for (int iterations : solves) reused.recordIterations(iterations);
  }
  return built;
}
}  // namespace

TEST(ReusedPreconditioner, StalePreconditionerGivesTheSameSolution) {
  const Mesh m = bedMesh();
  const PressureProblem earlier(m), now(m, 0.01);
  for (PreconditionerType type : {PreconditionerType::BlockCholesky, PreconditionerType::BoomerAmg}) {
    LinearSolverSettings settings = kTight;
    settings.preconditioner = type;
    ScalarField fresh(m.nLocalCells(), 0.0), stale(m.nLocalCells(), 0.0);
    const SolveStats f = KrylovSolver(now.A, settings).pcg(fresh, now.b);
    ReusedPreconditioner reused(type, 20);
    reused.forStep(earlier.A);
    const SolveStats s = KrylovSolver(now.A, settings, reused.forStep(now.A)).pcg(stale, now.b);
    ASSERT_FALSE(reused.builtThisStep());  // the second step used the first step's preconditioner
    ASSERT_TRUE(f.converged);
    ASSERT_TRUE(s.converged);
    const double diff = maxRelativeDifference(m, stale, fresh);
    if (m.rank() == 0)
      std::printf("[measured] %d ranks, %s: PCG iterations fresh %d, one step stale %d; max |dx| / max |x| "
                  "%.2e\n", m.nRanks(), type == PreconditionerType::BoomerAmg ? "boomeramg" : "block_cholesky",
                  f.iterations, s.iterations, diff);
    EXPECT_LT(diff, 1e-9);
  }
}

TEST(ReusedPreconditioner, RebuiltAfterMaxStepsOrWhenExcessIterationsPayForABuild) {
  const Mesh m = bedMesh();
  const PressureProblem p(m);
  EXPECT_EQ(buildPattern(PreconditionerType::BlockCholesky, 3, p.A, std::vector<std::vector<int>>(7, {5})),
            "B..B..B");
  // A block_cholesky build costs 30 iterations. Fresh 5: 20 and 20 cost 15 + 15 = 30 beyond it, so the
  // next step rebuilds; 19 and 20 cost 29 and keep it.
  EXPECT_EQ(buildPattern(PreconditionerType::BlockCholesky, 100, p.A, {{5}, {20}, {20}, {5}}), "B..B");
  EXPECT_EQ(buildPattern(PreconditionerType::BlockCholesky, 100, p.A, {{5}, {19}, {20}, {5}}), "B...");
  // Each solve of a step is held against the same solve of the build step (BoomerAMG: a build costs 20):
  // first solves 10, 10, 10 and second solves 4, 14, 14 cost 10 per step, so the fourth step rebuilds.
  EXPECT_EQ(buildPattern(PreconditionerType::BoomerAmg, 100, p.A, {{10, 4}, {10, 14}, {10, 14}, {10, 14}}),
            "B..B");
}

TEST(ReusedPreconditioner, ReuseIsAPressureSetting) {
  const std::string base = kSmallGasCase;
  EXPECT_EQ(GasConfig(YAML::Load(base)).settings().solver.pressure.preconditionerReuse, 20);
  EXPECT_EQ(GasConfig(YAML::Load(base + "solver: {pressure: {preconditioner_reuse: 1}}"))
                .settings().solver.pressure.preconditionerReuse, 1);
  try {
    GasConfig(YAML::Load(base + "solver: {pressure: {preconditioner_reuse: 0}}"));
    FAIL() << "preconditioner_reuse 0 was accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("preconditioner_reuse"), std::string::npos) << e.what();
  }
  EXPECT_THROW(GasConfig(YAML::Load(base + "solver: {momentum: {preconditioner_reuse: 5}}")), ConfigError);
}
