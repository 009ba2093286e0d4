#pragma once
// A pressure-like Poisson problem for the preconditioner tests: a_f Dt_f of a PISO pressure equation,
// small in the bed (drag-dominated) and varying with the gas fraction there, large in the freeboard;
// outlet cells get the fixed-pressure boundary coefficient. `bedShift` moves the bed's pattern
// (in m), as a later gas step would: a nearby matrix.
#include <mpi.h>

#include <cmath>

#include "cfd/fvm.hpp"
#include "cfd/ldu_matrix.hpp"
#include "cfd/mesh_builder.hpp"

namespace parcelflow::cfd {

// The Goldschmidt bed's proportions (0.15 x 0.015 x 0.7 m) at half its resolution.
inline Mesh bedMesh() {
  MeshSettings s;
  s.lengths = Vec3(0.15, 0.015, 0.7);
  s.cells = {24, 3, 48};
  return MeshBuilder::build(s, Geometry(), MPI_COMM_WORLD);
}

struct PressureProblem {
  explicit PressureProblem(const Mesh& m, double bedShift = 0.0) : A(m), b(m.nOwnedCells()) {
    ScalarField gamma(m.nInternalFaces());
    for (int f = 0; f < m.nInternalFaces(); ++f) {
      const Vec3& x = m.faceCentre(f);
      gamma[f] = x[2] < 0.3 ? 1e-4 * (1.5 + std::sin(60.0 * (x[0] - bedShift)) * std::cos(40.0 * x[2]))
                            : 2e-3;
    }
    fvm::laplacian(A, gamma);
    const double dz = 0.7 / 48;
    ScalarField outlet(m.nOwnedCells(), 0.0);
    for (int c = 0; c < m.nOwnedCells(); ++c) {
      if (m.cellCentre(c)[2] > 0.7 - dz) outlet[c] = 2e-3 * (0.15 / 24) * (0.015 / 3) / (0.5 * dz);
      b[c] = std::cos(20.0 * m.cellCentre(c)[0]) * (m.cellCentre(c)[2] < 0.3 ? 1e-6 : 1e-8);
    }
    fvm::Sp(A, outlet);
  }
  LduMatrix A;
  ScalarField b;
};

}  // namespace parcelflow::cfd
