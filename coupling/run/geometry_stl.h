// The LIGGGHTS variable geometry_stl (issue 31, "geometry once"): case.yaml's `geometry` as one closed surface
// in an ASCII STL file in the output folder, written before the LIGGGHTS script runs, so that a script's
// `fix mesh/surface file ${geometry_stl}` gives the parcels the walls the gas has, from the same primitives or
// STL files (cfd/geometry/surface_from_geometry.hpp: round primitives as 128-gons; no geometry: the mesh's box).
#pragma once

#include <mpi.h>

#include <string>

#include "cfd/solver/gas_settings.hpp"

namespace parcelflow::coupling {

// Rank 0 writes OUTPUT_FOLDER/geometry.stl; returns its absolute path on every rank. Collective; a file that
// cannot be written is a ConfigError on every rank.
std::string writeGeometryStl(const cfd::GasSettings& gas, const std::string& output_folder, MPI_Comm comm);

}  // namespace parcelflow::coupling
