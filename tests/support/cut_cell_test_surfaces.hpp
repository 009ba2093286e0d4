#pragma once
// Surfaces and STL files for the cut-cell tests, written independently of the code under test (own
// STL writer, own box and sphere triangulations).
#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "cfd/geometry/triangle_surface.hpp"

namespace parcelflow::cfd::test {

// A file in the temporary directory, removed when the test's scope ends, also when it ends by an exception.
class TempFile {
 public:
  explicit TempFile(const std::string& name)
      : path_((std::filesystem::temp_directory_path() / ("parcelflow_cut_cell_" + name)).string()) {}
  ~TempFile() { std::remove(path_.c_str()); }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

inline TriangleSurface boxSurface(const Vec3& lo, const Vec3& hi) {
  TriangleSurface s;
  for (int b = 0; b < 8; ++b) s.points.emplace_back(b & 1 ? hi[0] : lo[0], b & 2 ? hi[1] : lo[1], b & 4 ? hi[2] : lo[2]);
  s.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return s;
}

// Icosahedron subdivided `levels` times, corners projected onto the sphere.
inline TriangleSurface sphereSurface(const Vec3& centre, double radius, int levels) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3> p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& q : p) q.normalize();
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9},
                                       {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> middle;
    auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = middle.find(key);
      if (it != middle.end()) return it->second;
      p.push_back((p[a] + p[b]).normalized());
      return middle[key] = static_cast<int>(p.size()) - 1;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& tri : f) {
      const int a = mid(tri[0], tri[1]), b = mid(tri[1], tri[2]), c = mid(tri[2], tri[0]);
      next.insert(next.end(), {{tri[0], a, c}, {tri[1], b, a}, {tri[2], c, b}, {a, b, c}});
    }
    f = next;
  }
  TriangleSurface s;
  for (const auto& q : p) s.points.push_back(centre + radius * q);
  s.triangles = f;
  return s;
}

inline TriangleSurface transformed(TriangleSurface s, const Eigen::Matrix3d& rotation, const Vec3& about) {
  for (auto& q : s.points) q = about + rotation * (q - about);
  return s;
}

inline Vec3 unitNormal(const TriangleSurface& s, const std::array<int, 3>& t) {
  return (s.points[t[1]] - s.points[t[0]]).cross(s.points[t[2]] - s.points[t[0]]).normalized();
}

inline void writeAsciiStl(const TriangleSurface& s, const std::string& path) {
  std::FILE* out = std::fopen(path.c_str(), "w");
  std::fprintf(out, "solid test\n");
  for (const auto& t : s.triangles) {
    const Vec3 n = unitNormal(s, t);
    std::fprintf(out, "facet normal %.17g %.17g %.17g\nouter loop\n", n[0], n[1], n[2]);
    for (int c = 0; c < 3; ++c) {
      const Vec3& q = s.points[t[c]];
      std::fprintf(out, "vertex %.17g %.17g %.17g\n", q[0], q[1], q[2]);
    }
    std::fprintf(out, "endloop\nendfacet\n");
  }
  std::fprintf(out, "endsolid test\n");
  std::fclose(out);
}

inline void writeBinaryStl(const TriangleSurface& s, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  const std::string header(80, ' ');
  out.write(header.data(), 80);
  const std::uint32_t count = static_cast<std::uint32_t>(s.triangles.size());
  out.write(reinterpret_cast<const char*>(&count), 4);
  for (const auto& t : s.triangles) {
    float v[12];
    const Vec3 n = unitNormal(s, t);
    for (int c = 0; c < 3; ++c) v[c] = static_cast<float>(n[c]);
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) v[3 + 3 * k + c] = static_cast<float>(s.points[t[k]][c]);
    out.write(reinterpret_cast<const char*>(v), sizeof v);
    const std::uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(&attributes), 2);
  }
}

}  // namespace parcelflow::cfd::test
