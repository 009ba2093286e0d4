// The side walls a bed of parcels packs against, as wall area per volume of gas (issue 29). Coarse-grained
// parcels pack looser along a wall than the particles they stand for: their centres keep D/2 off it, the
// particles' d/2, and the loose layer is about (D - d)/2 thicker. The share of the bed in that layer is
// (D - d) times this area per volume (4 (D - d) / W for a square bed of width W): parcel_size_report.h.
#pragma once

#include <array>
#include <vector>

#include "cfd/solver/gas_settings.hpp"
#include "cfd/mesh/mesh.hpp"

namespace parcelflow::coupling {

// Area of the wall faces (no-slip or free-slip) whose normal is across gravity (|n . g| < |g| / 2; every wall
// face when gravity is zero), over the gas volume. Faces of the gas box normal to an axis along which the
// DEM box is periodic do not count: the parcels pass through there. Collective over the mesh's ranks.
double sideWallAreaPerVolume(const cfd::Mesh& mesh, const std::vector<cfd::BoundarySettings>& boundaries,
                             const cfd::Vec3& gravity, const std::array<bool, 3>& dem_periodic);

// The box's smallest length along an axis that is not periodic for the DEM (parcels pass through the faces of
// a periodic axis, so no wall bounds the bed there); infinity when every axis is periodic.
double narrowestExtentBetweenWalls(const std::array<double, 3>& box_lengths, const std::array<bool, 3>& dem_periodic);

}  // namespace parcelflow::coupling
