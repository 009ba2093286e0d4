#pragma once
// fvc:: explicit finite-volume operators: they return fields computed from known values (the
// counterpart of the implicit fvm:: operators, as in OpenFOAM). Cell results are computed on owned
// cells and then copied to the ghosts.
#include <Eigen/Core>
#include <vector>

#include "cfd/mesh/mesh.hpp"
#include "cfd/base/types.hpp"

namespace parcelflow::cfd {

using TensorField = std::vector<Eigen::Matrix3d>;  // J(i, j) = d u_i / d x_j

namespace fvc {

// Linear interpolation to internal face f, w x_owner + (1 - w) x_neighbour, of the cell value `value(c)` (a
// field's entry, one of its components, a row of a tensor). Every face value of the solver is this expression.
template <class T, class CellValue>
T interpolate(const Mesh& mesh, int f, const CellValue& value) {
  const double w = mesh.faceWeight(f);
  return T(w * value(mesh.faceOwner(f)) + (1.0 - w) * value(mesh.faceNeighbour(f)));
}
template <class T>
T interpolate(const Mesh& mesh, const std::vector<T>& cells, int f) {
  return interpolate<T>(mesh, f, [&cells](int c) -> const T& { return cells[c]; });
}

// Linear interpolation to internal faces (cell field with valid ghosts).
ScalarField interpolate(const Mesh& mesh, const ScalarField& cells);
VectorField interpolate(const Mesh& mesh, const VectorField& cells);
// Gauss gradient with linear face values; `boundary` holds one value per boundary face.
VectorField grad(const Mesh& mesh, const ScalarField& cells, const ScalarField& boundary);
TensorField grad(const Mesh& mesh, const VectorField& cells, const VectorField& boundary);
// Sum of outward face fluxes per owned cell (internal fluxes oriented owner -> neighbour).
ScalarField surfaceSum(const Mesh& mesh, const ScalarField& internalFlux,
                       const ScalarField& boundaryFlux);
VectorField surfaceSum(const Mesh& mesh, const VectorField& internalFlux,
                       const VectorField& boundaryFlux);

}  // namespace fvc
}  // namespace parcelflow::cfd
