#pragma once
// Conservative smoothing of a cell field by implicit diffusion (the diffusion-based coarse graining of
// Sun & Xiao, J. Comput. Phys. 2015, and MFiX's DES_DIFFUSE_WIDTH): one backward-Euler step of
// ds/dtau = div(grad s) over the pseudo-time tau = L^2,
//     V_c s_c - L^2 sum_f |S_f| / delta_f (s_N - s_c) = V_c s0_c,
// with no flux through any boundary face. The matrix is symmetric positive definite (the cell volumes on
// its diagonal), the face terms cancel in the sum over cells, so sum V s = sum V s0 to the solve's
// tolerance (1e-12 of the right side), and a uniform field stays uniform. The matrix is an M-matrix whose
// rows sum to V_c, so the smoothed field stays within the input's extremes (nonnegative stays nonnegative).
// On a line of cells of width h a unit spike becomes rho^|i| / sqrt(1 + 4k) with k = L^2/h^2 and
// rho = (1 + 2k - sqrt(1 + 4k)) / (2k): the screened-Poisson kernel exp(-r/L) of range L (its rms radius in
// 3D is sqrt(6) L).
// Why: a parcel larger than the cells deposits its volume into few cells, so the solids fraction of a packed
// bed of parcels scatters from cell to cell far more than the particles' (issue 29); the gas-fraction floor
// then cuts the scattered peaks off and the bed loses solid volume that the gas and the drag should see.
#include <memory>
#include <vector>

#include "cfd/linear/krylov_solver.hpp"
#include "cfd/linear/ldu_matrix.hpp"
#include "cfd/mesh/mesh.hpp"

namespace parcelflow::cfd {

class DiffusionSmoother {
 public:
  // length L > 0 [m]; builds the matrix and its preconditioner once (collective).
  DiffusionSmoother(const Mesh& mesh, double length);
  // owned: values on the owned cells, replaced by the smoothed values (collective). Returns the solve's
  // statistics; a solve that did not converge is an internal error (the matrix is well conditioned).
  SolveStats apply(std::vector<double>& owned);
  double length() const { return length_; }

 private:
  const Mesh& mesh_;
  double length_;
  LduMatrix matrix_;
  std::unique_ptr<KrylovSolver> solver_;
  ScalarField x_, b_;
};

}  // namespace parcelflow::cfd
