#pragma once
// Reads the fluid's boundary from an STL file (ASCII or binary; CGAL's reader, which merges identical
// corner points into shared vertices) and checks that it bounds a solid: closed, manifold, consistently
// oriented with outward normals (positive enclosed volume), not self-intersecting. Any problem stops
// with a ConfigError naming `key`, the file and what is wrong: a leaky or inverted surface would
// otherwise give wrong fluid volumes without any sign.
#include <string>

#include "cfd/geometry/triangle_surface.hpp"

namespace parcelflow::cfd {

// `key` names the setting that gave the path in messages (e.g. "geometry.stl").
TriangleSurface readStlSurface(const std::string& path, const std::string& key);

}  // namespace parcelflow::cfd
