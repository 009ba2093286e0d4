#pragma once
// Writes a closed triangulated surface as an ASCII STL file (outward normals, 17 significant digits), the
// form LIGGGHTS' `fix mesh/surface file` and CAD programs read.
#include <string>

#include "cfd/geometry/triangle_surface.hpp"

namespace parcelflow::cfd {

// Throws ConfigError naming `path` when the file cannot be written.
void writeAsciiStl(const TriangleSurface& surface, const std::string& path, const std::string& solidName);

}  // namespace parcelflow::cfd
