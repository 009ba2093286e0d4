#pragma once
// The gas part of a checkpoint: GasSolver::State in one HDF5 file, keyed by global ids so that it can be
// read back on any number of ranks. Cells: /cell_id, /alpha, /p_rgh, /velocity. Internal faces:
// /face_cells (the global ids of owner and neighbour, owner < neighbour) and /phi, written by the rank that
// owns the owner cell, with /face_centre. Boundary faces: /boundary_key (global cell id, outward axis
// direction 0..5), /boundary_centre and /phi_b. A face is found by its cells (boundary: its cell) and the
// nearest centre, which tells a merged cut cell's two faces to one neighbour apart and does not depend on the
// axis direction of a cut wall facing 45 degrees between two axes. Files without the centres (older ones) are
// read by cell pairs and, for boundary faces, axis direction.
// Root attributes: checkpoint_id, time, global_cells.
#include <string>

#include "cfd/solver/gas_solver.hpp"

namespace parcelflow::cfd {

// Collective. Throws std::runtime_error if the file cannot be written completely.
void writeGasCheckpoint(const GasSolver& gas, const std::string& path, const std::string& checkpoint_id);

// Collective. Throws ConfigError naming the file when its id is not `checkpoint_id` or it does not fit
// this mesh (another cell count, a cell or face of this mesh missing).
void readGasCheckpoint(GasSolver& gas, const std::string& path, const std::string& checkpoint_id);

}  // namespace parcelflow::cfd
