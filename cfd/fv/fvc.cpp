#include "cfd/fv/fvc.hpp"

namespace parcelflow::cfd::fvc {

namespace {
template <class T>
std::vector<T> interpolateT(const Mesh& mesh, const std::vector<T>& cells) {
  std::vector<T> faces(mesh.nInternalFaces());
  for (int f = 0; f < mesh.nInternalFaces(); ++f) faces[f] = interpolate(mesh, cells, f);
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

namespace {
// The flux of a face value through an area vector, and the part of a gradient an axis-aligned face adds to.
Vec3 faceFlux(double value, const Vec3& area) { return value * area; }
Eigen::Matrix3d faceFlux(const Vec3& value, const Vec3& area) { return value * area.transpose(); }
double& axisPart(Vec3& g, int axis) { return g[axis]; }
Eigen::Block<Eigen::Matrix3d, 3, 1, true> axisPart(Eigen::Matrix3d& g, int axis) { return g.col(axis); }

// Gauss gradient: sum over the faces of face value times area vector, over the cell volume. The face values
// are interpolated and summed into the cells face by face (the order of fvc::surfaceSum), without face fields.
// An internal face's area vector has one non-zero component, so only that part of the gradient takes its
// flux (what the full product would add elsewhere is exactly zero).
template <class Value, class Gradient>
std::vector<Gradient> gaussGrad(const Mesh& mesh, const std::vector<Value>& cells,
                                const std::vector<Value>& boundary) {
  const int nOwned = mesh.nOwnedCells();
  std::vector<Gradient> g(mesh.nLocalCells(), Gradient::Zero());
  for (int f = 0; f < mesh.nInternalFaces(); ++f) {
    const int o = mesh.faceOwner(f), n = mesh.faceNeighbour(f), k = mesh.faceAxis(f);
    const Value flux = interpolate(mesh, cells, f) * mesh.faceArea(f)[k];
    if (o < nOwned) axisPart(g[o], k) += flux;
    if (n < nOwned) axisPart(g[n], k) -= flux;
  }
  for (int b = 0; b < mesh.nBoundaryFaces(); ++b)
    g[mesh.boundaryCell(b)] += faceFlux(boundary[b], mesh.boundaryArea(b));
  for (int c = 0; c < nOwned; ++c) g[c] /= mesh.cellVolume(c);
  return g;
}
}  // namespace

VectorField grad(const Mesh& mesh, const ScalarField& cells, const ScalarField& boundary) {
  VectorField g = gaussGrad<double, Vec3>(mesh, cells, boundary);
  mesh.exchange(g);
  return g;
}

TensorField grad(const Mesh& mesh, const VectorField& cells, const VectorField& boundary) {
  TensorField g = gaussGrad<Vec3, Eigen::Matrix3d>(mesh, cells, boundary);
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
