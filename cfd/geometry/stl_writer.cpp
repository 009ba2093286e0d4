#include "cfd/geometry/stl_writer.hpp"

#include <Eigen/Geometry>  // cross products
#include <cstdio>
#include <memory>

#include "cfd/base/config_error.hpp"

namespace parcelflow::cfd {

void writeAsciiStl(const TriangleSurface& surface, const std::string& path, const std::string& solidName) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!file) throw ConfigError("cannot write the STL file '" + path + "'");
  std::FILE* out = file.get();
  std::fprintf(out, "solid %s\n", solidName.c_str());
  for (const auto& t : surface.triangles) {
    const Vec3& a = surface.points[t[0]];
    const Vec3 n = (surface.points[t[1]] - a).cross(surface.points[t[2]] - a).normalized();
    std::fprintf(out, "  facet normal %.17g %.17g %.17g\n    outer loop\n", n[0], n[1], n[2]);
    for (int c = 0; c < 3; ++c) {
      const Vec3& p = surface.points[t[c]];
      std::fprintf(out, "      vertex %.17g %.17g %.17g\n", p[0], p[1], p[2]);
    }
    std::fprintf(out, "    endloop\n  endfacet\n");
  }
  if (std::fprintf(out, "endsolid %s\n", solidName.c_str()) < 0 || std::fflush(out) != 0)
    throw ConfigError("cannot write the STL file '" + path + "' (disk full?)");
}

}  // namespace parcelflow::cfd
