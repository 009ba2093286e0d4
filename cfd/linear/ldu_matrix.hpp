#pragma once
// A distributed sparse matrix in face-addressed (lower/diagonal/upper) form: one row per owned cell;
// for internal face f, upper[f] multiplies the neighbour value in the owner's row and lower[f] the
// owner value in the neighbour's row. Rows of ghost cells are not stored (their owners hold them).
#include <Eigen/SparseCore>

#include "cfd/mesh/mesh.hpp"
#include "cfd/base/types.hpp"

namespace parcelflow::cfd {

class LduMatrix {
 public:
  explicit LduMatrix(const Mesh& mesh);

  const Mesh& mesh() const { return *mesh_; }
  ScalarField& diag() { return diag_; }
  const ScalarField& diag() const { return diag_; }
  ScalarField& upper() { return upper_; }
  const ScalarField& upper() const { return upper_; }
  ScalarField& lower() { return lower_; }
  const ScalarField& lower() const { return lower_; }

  // Adds a symmetric face coupling g (diagonal +g, off-diagonal -g), as a diffusion term does.
  void addSymmetric(int face, double g);
  // y = A x on owned rows; x is a local field whose ghosts are refreshed here.
  void multiply(ScalarField& x, ScalarField& y) const;
  // y = (A + diag(extraDiag)) x.
  void multiply(ScalarField& x, ScalarField& y, const ScalarField& extraDiag) const;
  // The owned-owned block (couplings to ghosts dropped), for the block-Jacobi preconditioner.
  Eigen::SparseMatrix<double> localBlock(const ScalarField& extraDiag) const;

 private:
  const Mesh* mesh_;
  ScalarField diag_, upper_, lower_;
};

}  // namespace parcelflow::cfd
