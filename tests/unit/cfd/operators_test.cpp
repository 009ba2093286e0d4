// fvc/fvm operators and the distributed Krylov solvers: the Gauss gradient is exact for linear fields,
// and PCG / BiCGStab solve a Laplacian to the requested tolerance on any number of ranks.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>

#include "cfd/fv/fvc.hpp"
#include "cfd/fv/fvm.hpp"
#include "cfd/linear/krylov_solver.hpp"
#include "cfd/mesh/mesh_builder.hpp"

using namespace parcelflow::cfd;

namespace {
Mesh boxMesh() {
  MeshSettings s;
  s.lengths = Vec3(1.0, 0.5, 2.0);
  s.cells = {6, 5, 12};
  return MeshBuilder::build(s, Geometry(), MPI_COMM_WORLD);
}
}  // namespace

TEST(Operators, GaussGradientExactForLinearField) {
  const Mesh m = boxMesh();
  const Vec3 g(1.5, -2.0, 0.25);
  ScalarField f(m.nLocalCells()), fb(m.nBoundaryFaces());
  for (int c = 0; c < m.nLocalCells(); ++c) f[c] = 3.0 + g.dot(m.cellCentre(c));
  for (int b = 0; b < m.nBoundaryFaces(); ++b) fb[b] = 3.0 + g.dot(m.boundaryCentre(b));
  const VectorField grad = fvc::grad(m, f, fb);
  for (int c = 0; c < m.nLocalCells(); ++c) EXPECT_LT((grad[c] - g).norm(), 1e-12);
}

TEST(Operators, KrylovSolversConvergeOnLaplacian) {
  const Mesh m = boxMesh();
  LduMatrix A(m);
  fvm::laplacian(A, ScalarField(m.nInternalFaces(), 1.0));
  ScalarField shift(m.nOwnedCells(), 1e-2);
  fvm::Sp(A, shift);
  ScalarField b(m.nOwnedCells());
  for (int c = 0; c < m.nOwnedCells(); ++c) b[c] = std::sin(7.0 * m.cellCentre(c)[0]) + m.cellCentre(c)[2];
  for (auto type : {PreconditionerType::Jacobi, PreconditionerType::BlockIncompleteCholesky,
                    PreconditionerType::BlockCholesky}) {
    LinearSolverSettings settings{1e-12, 1e-300, 2000, type};
    ScalarField x(m.nLocalCells(), 0.0), y(m.nLocalCells(), 0.0);
    const SolveStats stats = KrylovSolver(A, settings).pcg(x, b);
    EXPECT_TRUE(stats.converged);
    A.multiply(x, y);
    double r = 0, n = 0;
    for (int c = 0; c < m.nOwnedCells(); ++c) r += (y[c] - b[c]) * (y[c] - b[c]), n += b[c] * b[c];
    EXPECT_LT(std::sqrt(m.sum(r) / m.sum(n)), 1e-11);
  }
  // Non-symmetric: add upwind convection and use BiCGStab.
  fvm::convectionUpwind(A, ScalarField(m.nInternalFaces(), 0.3));
  LinearSolverSettings settings{1e-12, 1e-300, 2000, PreconditionerType::Jacobi};
  ScalarField x(m.nLocalCells(), 0.0), y(m.nLocalCells(), 0.0);
  const SolveStats stats = KrylovSolver(A, settings).bicgstab(x, b);
  EXPECT_TRUE(stats.converged);
  A.multiply(x, y);
  double r = 0, n = 0;
  for (int c = 0; c < m.nOwnedCells(); ++c) r += (y[c] - b[c]) * (y[c] - b[c]), n += b[c] * b[c];
  EXPECT_LT(std::sqrt(m.sum(r) / m.sum(n)), 1e-11);
}
