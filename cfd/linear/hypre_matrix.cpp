#include "cfd/linear/hypre_matrix.hpp"

#include <HYPRE.h>

#include <algorithm>
#include <vector>

#include "cfd/linear/hypre_library.hpp"

namespace parcelflow::cfd {

namespace {
// Global hypre row of every local cell, owned and ghost (exact in a double up to 2^53 rows).
ScalarField globalRows(const Mesh& mesh, HYPRE_BigInt firstRow) {
  ScalarField rows(mesh.nLocalCells(), -1.0);
  for (int c = 0; c < mesh.nOwnedCells(); ++c) rows[c] = static_cast<double>(firstRow + c);
  mesh.exchange(rows);
  return rows;
}
}  // namespace

HypreMatrix::HypreMatrix(const LduMatrix& matrix, const ScalarField& extraDiag)
    : comm_(matrix.mesh().comm()), nOwned_(matrix.mesh().nOwnedCells()) {
  initialiseHypreOnce();
  const Mesh& mesh = matrix.mesh();
  long owned = nOwned_, before = 0;
  MPI_Exscan(&owned, &before, 1, MPI_LONG, MPI_SUM, comm_);
  if (mesh.rank() == 0) before = 0;  // MPI_Exscan leaves rank 0's result undefined
  firstRow_ = static_cast<HYPRE_BigInt>(before);
  const ScalarField rows = globalRows(mesh, firstRow_);

  // Rows in CSR form, diagonal first; faces to ghosts go to hypre's off-diagonal (other rank) part.
  std::vector<std::vector<HYPRE_BigInt>> cols(nOwned_);
  std::vector<std::vector<double>> values(nOwned_);
  std::vector<HYPRE_Int> nDiagBlock(nOwned_, 1), nOffdBlock(nOwned_, 0);
  for (int c = 0; c < nOwned_; ++c) {
    cols[c].push_back(firstRow_ + c);
    values[c].push_back(matrix.diag()[c] + (extraDiag.empty() ? 0.0 : extraDiag[c]));
  }
  // A merged cut cell (cell_groups.hpp) can share two faces with one neighbour: one entry per column.
  const auto couple = [&](int row, int col, double value) {
    const auto id = static_cast<HYPRE_BigInt>(rows[col]);
    const auto it = std::find(cols[row].begin() + 1, cols[row].end(), id);
    if (it != cols[row].end()) {
      values[row][it - cols[row].begin()] += value;
      return;
    }
    cols[row].push_back(id);
    values[row].push_back(value);
    ++(col < nOwned_ ? nDiagBlock : nOffdBlock)[row];
  };
  for (int f = 0; f < mesh.nInternalFaces(); ++f) {
    const int o = mesh.faceOwner(f), n = mesh.faceNeighbour(f);
    if (o < nOwned_) couple(o, n, matrix.upper()[f]);
    if (n < nOwned_) couple(n, o, matrix.lower()[f]);
  }
  std::vector<HYPRE_Int> nCols(nOwned_);
  std::vector<HYPRE_BigInt> rowIds(nOwned_), flatCols;
  std::vector<double> flatValues;
  for (int c = 0; c < nOwned_; ++c) {
    nCols[c] = static_cast<HYPRE_Int>(cols[c].size());
    rowIds[c] = firstRow_ + c;
    flatCols.insert(flatCols.end(), cols[c].begin(), cols[c].end());
    flatValues.insert(flatValues.end(), values[c].begin(), values[c].end());
  }

  const HYPRE_BigInt lastRow = firstRow_ + nOwned_ - 1;
  HYPRE_IJMatrix ij = nullptr;
  PARCELFLOW_HYPRE_CALL(HYPRE_IJMatrixCreate(comm_, firstRow_, lastRow, firstRow_, lastRow, &ij));
  ij_.reset(ij);
  PARCELFLOW_HYPRE_CALL(HYPRE_IJMatrixSetObjectType(ij, HYPRE_PARCSR));
  PARCELFLOW_HYPRE_CALL(HYPRE_IJMatrixSetDiagOffdSizes(ij, nDiagBlock.data(), nOffdBlock.data()));
  PARCELFLOW_HYPRE_CALL(HYPRE_IJMatrixInitialize(ij));
  PARCELFLOW_HYPRE_CALL(HYPRE_IJMatrixSetValues(ij, nOwned_, nCols.data(), rowIds.data(),
                                                flatCols.data(), flatValues.data()));
  PARCELFLOW_HYPRE_CALL(HYPRE_IJMatrixAssemble(ij));
  void* object = nullptr;
  PARCELFLOW_HYPRE_CALL(HYPRE_IJMatrixGetObject(ij, &object));
  parcsr_ = static_cast<HYPRE_ParCSRMatrix>(object);
}

}  // namespace parcelflow::cfd
