#include "cfd/fv/fvm.hpp"

#include <algorithm>

namespace parcelflow::cfd::fvm {

void laplacian(LduMatrix& m, const ScalarField& gammaFace) {
  const Mesh& mesh = m.mesh();
  for (int f = 0; f < mesh.nInternalFaces(); ++f)
    m.addSymmetric(f, gammaFace[f] * mesh.faceMagArea(f) / mesh.faceDelta(f));
}

void convectionUpwind(LduMatrix& m, const ScalarField& massFlux) {
  const Mesh& mesh = m.mesh();
  const int nOwned = mesh.nOwnedCells();
  for (int f = 0; f < mesh.nInternalFaces(); ++f) {
    const int o = mesh.faceOwner(f), n = mesh.faceNeighbour(f);
    const double F = massFlux[f];
    // Flow into the neighbour (F > 0) makes the owner value upstream of the neighbour's row, and
    // vice versa; the cell's own outflow cancels against x_P.
    const double intoNeighbour = std::max(F, 0.0), intoOwner = std::max(-F, 0.0);
    if (n < nOwned) {
      m.diag()[n] += intoNeighbour;
      m.lower()[f] -= intoNeighbour;
    }
    if (o < nOwned) {
      m.diag()[o] += intoOwner;
      m.upper()[f] -= intoOwner;
    }
  }
}

void Sp(LduMatrix& m, const ScalarField& coeff) {
  for (int c = 0; c < m.mesh().nOwnedCells(); ++c) m.diag()[c] += coeff[c];
}

}  // namespace parcelflow::cfd::fvm
