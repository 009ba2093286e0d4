#pragma once
// fvm:: implicit finite-volume operators: they add coefficients to an LduMatrix (and, for deferred or
// known parts, to a source). Boundary-face contributions depend on the boundary condition and are
// added by the equation that owns the conditions (GasSolver).
#include "cfd/linear/ldu_matrix.hpp"
#include "cfd/base/types.hpp"

namespace parcelflow::cfd::fvm {

// - div(gamma grad x) on internal faces: coefficient gamma_f |S_f| / delta_f (orthogonal mesh).
void laplacian(LduMatrix& m, const ScalarField& gammaFace);
// Upwind convection in non-conservative form, sum_f F_f (x_f - x_P), with F_f = massFlux_f oriented
// owner -> neighbour. Bounded: only adds to the diagonal and negative off-diagonals.
void convectionUpwind(LduMatrix& m, const ScalarField& massFlux);
// Implicit source coefficient per owned cell: diag += coeff (already integrated over the cell).
void Sp(LduMatrix& m, const ScalarField& coeff);

}  // namespace parcelflow::cfd::fvm
