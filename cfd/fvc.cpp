#include "fvc.hpp"

namespace parcelflow::cfd::fvc {

namespace {
template <class T>
std::vector<T> interpolateT(const Mesh& mesh, const std::vector<T>& cells) {
  std::vector<T> faces(mesh.nInternalFaces());
  for (int f = 0; f < mesh.nInternalFaces(); ++f) {
    const double w = mesh.faceWeight(f);
    faces[f] = w * cells[mesh.faceOwner(f)] + (1.0 - w) * cells[mesh.faceNeighbour(f)];
  }
  return faces;
}

template <class T>
std::vector<T> surfaceSumT(const Mesh& mesh, const std::vector<T>& internal,
                           const std::vector<T>& boundary, const T& zero) {
  const int nOwned = mesh.nOwnedCells();
  std::vector<T> out(nOwned, zero);
  for (int f = 0; f < mesh.nInternalFaces(); ++f) {
    const int o = mesh.faceOwner(f), n = mesh.faceNeighbour(f);
    if (o < nOwned) out[o] += internal[f];
    if (n < nOwned) out[n] -= internal[f];
  }
  for (int b = 0; b < mesh.nBoundaryFaces(); ++b) out[mesh.boundaryCell(b)] += boundary[b];
  return out;
}
}  // namespace

ScalarField interpolate(const Mesh& mesh, const ScalarField& cells) {
  return interpolateT(mesh, cells);
}

VectorField interpolate(const Mesh& mesh, const VectorField& cells) {
  return interpolateT(mesh, cells);
}

VectorField grad(const Mesh& mesh, const ScalarField& cells, const ScalarField& boundary) {
  const ScalarField faces = interpolate(mesh, cells);
  VectorField internal(mesh.nInternalFaces()), bnd(mesh.nBoundaryFaces());
  for (int f = 0; f < mesh.nInternalFaces(); ++f) internal[f] = faces[f] * mesh.faceArea(f);
  for (int b = 0; b < mesh.nBoundaryFaces(); ++b) bnd[b] = boundary[b] * mesh.boundaryArea(b);
  VectorField g = surfaceSumT(mesh, internal, bnd, Vec3(Vec3::Zero()));
  g.resize(mesh.nLocalCells(), Vec3::Zero());
  for (int c = 0; c < mesh.nOwnedCells(); ++c) g[c] /= mesh.cellVolume(c);
  mesh.exchange(g);
  return g;
}

TensorField grad(const Mesh& mesh, const VectorField& cells, const VectorField& boundary) {
  const VectorField faces = interpolate(mesh, cells);
  TensorField internal(mesh.nInternalFaces()), bnd(mesh.nBoundaryFaces());
  for (int f = 0; f < mesh.nInternalFaces(); ++f)
    internal[f] = faces[f] * mesh.faceArea(f).transpose();
  for (int b = 0; b < mesh.nBoundaryFaces(); ++b)
    bnd[b] = boundary[b] * mesh.boundaryArea(b).transpose();
  TensorField g = surfaceSumT(mesh, internal, bnd, Eigen::Matrix3d(Eigen::Matrix3d::Zero()));
  g.resize(mesh.nLocalCells(), Eigen::Matrix3d::Zero());
  for (int c = 0; c < mesh.nOwnedCells(); ++c) g[c] /= mesh.cellVolume(c);
  // Exchange the 9 components as three vector fields.
  for (int row = 0; row < 3; ++row) {
    VectorField part(mesh.nLocalCells());
    for (int c = 0; c < mesh.nLocalCells(); ++c) part[c] = g[c].row(row).transpose();
    mesh.exchange(part);
    for (int c = mesh.nOwnedCells(); c < mesh.nLocalCells(); ++c) g[c].row(row) = part[c].transpose();
  }
  return g;
}

ScalarField surfaceSum(const Mesh& mesh, const ScalarField& internalFlux,
                       const ScalarField& boundaryFlux) {
  return surfaceSumT(mesh, internalFlux, boundaryFlux, 0.0);
}

VectorField surfaceSum(const Mesh& mesh, const VectorField& internalFlux,
                       const VectorField& boundaryFlux) {
  return surfaceSumT(mesh, internalFlux, boundaryFlux, Vec3(Vec3::Zero()));
}

}  // namespace parcelflow::cfd::fvc
