#pragma once
// For the pressure solver tests: the smallest valid gas case (append a `solver:` map to try settings),
// and a pressure-like Poisson problem: a_f Dt_f of a PISO pressure equation,
// small in the bed (drag-dominated) and varying with the gas fraction there, large in the freeboard;
// outlet cells get the fixed-pressure boundary coefficient. `bedShift` moves the bed's pattern
// (in m), as a later gas step would: a nearby matrix.
#include <mpi.h>

#include <cmath>

#include "cfd/fv/fvm.hpp"
#include "cfd/linear/ldu_matrix.hpp"
#include "cfd/mesh/mesh_builder.hpp"

namespace parcelflow::cfd {

inline const char* const kSmallGasCase = R"(
mesh: {lengths: [1, 1, 1], cells: [2, 2, 2]}
gas: {density: 1.2, viscosity: 1.8e-5}
boundaries: {zmin: {type: wall}, zmax: {type: pressure_outlet}, xmin: {type: wall},
             xmax: {type: wall}, ymin: {type: wall}, ymax: {type: wall}}
)";

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
