#include "cfd/geometry/stl_reader.hpp"

#include <CGAL/IO/STL.h>

#include <filesystem>
#include <fstream>

#include "cfd/geometry/cgal_surface_mesh.hpp"
#include "cfd/base/config_error.hpp"

namespace parcelflow::cfd {

namespace {

constexpr const char* allowedStl =
    "an existing STL file (ASCII or binary) of a closed, consistently oriented surface with outward "
    "normals (fluid inside, positive volume) that does not intersect itself";

[[noreturn]] void fail(const std::string& key, const std::string& path, const std::string& problem) {
  throw ConfigError(key, path + " (" + problem + ")", allowedStl);
}

}  // namespace

TriangleSurface readStlSurface(const std::string& path, const std::string& key) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail(key, path, "no such file");
  if (!std::filesystem::is_regular_file(path, ec)) fail(key, path, "not a regular file");
  std::ifstream probe(path, std::ios::binary);
  if (!probe) fail(key, path, "cannot be opened for reading");
  probe.close();

  std::vector<cgal::Point> points;
  std::vector<std::array<int, 3>> triangles;
  bool read = false;
  try {
    read = CGAL::IO::read_STL(path, points, triangles);
  } catch (const std::exception& e) {
    fail(key, path, std::string("unreadable as STL: ") + e.what());
  }
  if (!read) fail(key, path, "unreadable as STL (neither a valid ASCII nor a valid binary STL)");
  // CGAL's reader accepts a file in which it finds no complete facet (a broken ASCII file): say so.
  if (triangles.empty()) fail(key, path, "unreadable as STL (no complete triangle in it)");

  cgal::Mesh mesh;
  const std::string problem = cgal::closedSurfaceProblem(points, triangles, mesh);
  if (!problem.empty()) fail(key, path, problem);

  TriangleSurface surface;
  surface.points.reserve(points.size());
  for (const auto& p : points) surface.points.push_back(cgal::toVec3(p));
  surface.triangles = std::move(triangles);
  return surface;
}

}  // namespace parcelflow::cfd
