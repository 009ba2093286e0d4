#pragma once
// The gas part of a checkpoint: GasSolver::State in one HDF5 file, keyed by global ids so that it can be
// read back on any number of ranks. Cells: /cell_id, /alpha, /p_rgh, /velocity. Internal faces:
// /face_cells (the global ids of owner and neighbour, owner < neighbour) and /phi, written by the rank that
// owns the owner cell, with /face_centre. Boundary faces: /boundary_key (global cell id, outward axis
// direction 0..5), /boundary_centre and /phi_b. A face is found by its cells (boundary: its cell) and the
// nearest centre, which tells a merged cut cell's faces to one neighbour apart and survives the last-bit
// differences of two builds of one cut-cell mesh (CGAL's corefinement orders its work by the addresses of
// its boxes, ID_FROM_BOX_ADDRESS, so a few cut cells' volumes and centroids differ by 1e-16 between builds:
// a cut-cell run continues from its checkpoint to round-off, not bit for bit; and a sliver face of 1e-17 of a
// cell can exist in one build and not the other: one the restarting build has and the file lacks stops the
// restart (exit 2, "cells and faces of this mesh missing"), one the file has and the build lacks is dropped.
// Storing the cut geometry in the checkpoint is the fix, not done yet). Files without the centres (older
// ones) are read by cell pairs and, for boundary faces, axis direction.
// Root attributes: checkpoint_id, time, global_cells.
#include <string>

#include "gas_solver.hpp"

namespace parcelflow::cfd {

// Collective. Throws std::runtime_error if the file cannot be written completely.
void writeGasCheckpoint(const GasSolver& gas, const std::string& path, const std::string& checkpoint_id);

// Collective. Throws ConfigError naming the file when its id is not `checkpoint_id` or it does not fit
// this mesh (another cell count, a cell or face of this mesh missing).
void readGasCheckpoint(GasSolver& gas, const std::string& path, const std::string& checkpoint_id);

}  // namespace parcelflow::cfd
