#include "cfd/linear/ldu_matrix.hpp"

namespace parcelflow::cfd {

LduMatrix::LduMatrix(const Mesh& mesh)
    : mesh_(&mesh),
      diag_(mesh.nOwnedCells(), 0.0),
      upper_(mesh.nInternalFaces(), 0.0),
      lower_(mesh.nInternalFaces(), 0.0) {}

void LduMatrix::addSymmetric(int face, double g) {
  const int nOwned = mesh_->nOwnedCells();
  const int o = mesh_->faceOwner(face), n = mesh_->faceNeighbour(face);
  if (o < nOwned) diag_[o] += g;
  if (n < nOwned) diag_[n] += g;
  upper_[face] -= g;
  lower_[face] -= g;
}

void LduMatrix::multiply(ScalarField& x, ScalarField& y) const {
  static const ScalarField none;
  multiply(x, y, none);
}

void LduMatrix::multiply(ScalarField& x, ScalarField& y, const ScalarField& extraDiag) const {
  mesh_->exchange(x);
  const int nOwned = mesh_->nOwnedCells();
  for (int c = 0; c < nOwned; ++c)
    y[c] = (diag_[c] + (extraDiag.empty() ? 0.0 : extraDiag[c])) * x[c];
  for (int f = 0; f < mesh_->nInternalFaces(); ++f) {
    const int o = mesh_->faceOwner(f), n = mesh_->faceNeighbour(f);
    if (o < nOwned) y[o] += upper_[f] * x[n];
    if (n < nOwned) y[n] += lower_[f] * x[o];
  }
}

Eigen::SparseMatrix<double> LduMatrix::localBlock(const ScalarField& extraDiag) const {
  const int nOwned = mesh_->nOwnedCells();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(nOwned + 2 * mesh_->nInternalFaces());
  for (int c = 0; c < nOwned; ++c)
    entries.emplace_back(c, c, diag_[c] + (extraDiag.empty() ? 0.0 : extraDiag[c]));
  for (int f = 0; f < mesh_->nInternalFaces(); ++f) {
    const int o = mesh_->faceOwner(f), n = mesh_->faceNeighbour(f);
    if (o < nOwned && n < nOwned) {
      entries.emplace_back(o, n, upper_[f]);
      entries.emplace_back(n, o, lower_[f]);
    }
  }
  Eigen::SparseMatrix<double> block(nOwned, nOwned);
  block.setFromTriplets(entries.begin(), entries.end());
  return block;
}

}  // namespace parcelflow::cfd
