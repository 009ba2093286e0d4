// Bad fluid surfaces stop with a ConfigError naming the setting, the file and what is wrong: missing,
// unreadable, open, inconsistently oriented, inverted, self-intersecting, or leaving no fluid cell.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "cfd/config_error.hpp"
#include "cfd/cut_cell_geometry.hpp"
#include "cfd/stl_reader.hpp"
#include "cut_cell_test_surfaces.hpp"

using namespace parcelflow::cfd;
using namespace parcelflow::cfd::test;

namespace {

// Runs `action`, expects a ConfigError whose message contains every one of `parts`.
template <class Action>
void expectConfigError(Action action, const std::vector<std::string>& parts) {
  try {
    action();
    ADD_FAILURE() << "no ConfigError";
  } catch (const ConfigError& e) {
    const std::string message = e.what();
    for (const auto& part : parts) EXPECT_NE(message.find(part), std::string::npos) << message << "\nlacks: " << part;
  }
}

void expectStlError(const TriangleSurface& surface, const std::string& name, const std::string& problem) {
  const TempFile file("input_" + name);
  writeAsciiStl(surface, file.path());
  expectConfigError([&] { readStlSurface(file.path(), "geometry.stl"); }, {"geometry.stl", file.path(), problem});
}

const TriangleSurface cube = boxSurface(Vec3(0.2, 0.2, 0.2), Vec3(0.8, 0.8, 0.8));

}  // namespace

TEST(CutCellInput, MissingFile) {
  const TempFile missing("input_does_not_exist.stl");  // never written
  expectConfigError([&] { readStlSurface(missing.path(), "geometry.stl"); },
                    {"geometry.stl", missing.path(), "no such file", "allowed is"});
}

TEST(CutCellInput, UnreadableFile) {
  const TempFile garbage("input_garbage.stl");
  std::ofstream(garbage.path()) << "solid broken\nfacet normal 0 0 1\nouter loop\nvertex 0 0 nonsense\n";
  expectConfigError([&] { readStlSurface(garbage.path(), "geometry.stl"); },
                    {"geometry.stl", garbage.path(), "unreadable"});
}

TEST(CutCellInput, OpenSurface) {
  TriangleSurface open = cube;
  open.triangles.pop_back();
  expectStlError(open, "open.stl", "not closed");
}

TEST(CutCellInput, InconsistentOrientation) {
  TriangleSurface flippedOne = cube;
  std::swap(flippedOne.triangles[3][1], flippedOne.triangles[3][2]);
  expectStlError(flippedOne, "flipped_one.stl", "consistently oriented");
}

TEST(CutCellInput, InvertedSurface) {
  TriangleSurface inverted = cube;
  for (auto& t : inverted.triangles) std::swap(t[1], t[2]);
  expectStlError(inverted, "inverted.stl", "inverted");
}

TEST(CutCellInput, SelfIntersectingSurface) {
  // Two overlapping cubes in one file: closed and oriented, but the solid is not well defined.
  TriangleSurface two = cube;
  const TriangleSurface other = boxSurface(Vec3(0.5, 0.5, 0.5), Vec3(0.9, 0.9, 0.9));
  for (const auto& t : other.triangles) two.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  two.points.insert(two.points.end(), other.points.begin(), other.points.end());
  expectStlError(two, "self_intersecting.stl", "intersects itself");
}

TEST(CutCellInput, NoFluidInTheMeshBox) {
  const CartesianBackground grid(Vec3(2, 2, 2), Vec3(1, 1, 1), {4, 4, 4});
  expectConfigError([&] { CutCellGeometry(cube, grid, "geometry.stl = far_away.stl"); },
                    {"geometry.stl = far_away.stl", "leaves fluid in at least one cell"});
}
