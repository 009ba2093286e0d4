// Bad fluid surfaces stop with a ConfigError naming the setting, the file and what is wrong: missing,
// unreadable, open, inconsistently oriented, inverted, self-intersecting, or leaving no fluid cell. An STL
// named in case.yaml (`{stl: {file: ...}}`) is found relative to the case folder and selects the cells
// whose centre is inside it.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cfd/base/config_error.hpp"
#include "cfd/geometry/cut_cell_geometry.hpp"
#include "cfd/solver/gas_config.hpp"
#include "cfd/geometry/stl_reader.hpp"
#include "tests/support/cut_cell_test_surfaces.hpp"

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

namespace {

const std::string caseWithStl(const std::string& file) {
  return "mesh: {origin: [0, 0, 0], lengths: [1, 1, 1], cells: [20, 20, 20]}\n"
         "geometry: [{shape: {box: {min: [0, 0, 0], max: [1, 1, 0.1]}}}, {shape: {stl: {file: " + file + "}}}]\n"
         "gas: {density: 1.0, viscosity: 1e-5}\n"
         "boundaries: {zmax: {type: pressure_outlet}, walls: {type: wall}}\n";
}

}  // namespace

TEST(CutCellInput, StlShapeInCaseYamlSelectsTheCellsInside) {
  // A cube of side 0.5 turned by 30 degrees about z and 20 about x, in the case folder (the temp directory).
  const Eigen::Matrix3d turn = (Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(M_PI / 9, Eigen::Vector3d::UnitX())).toRotationMatrix();
  const Vec3 centre(0.5, 0.5, 0.5);
  const TempFile file("input_turned_cube.stl");
  writeBinaryStl(transformed(boxSurface(centre - Vec3(0.25, 0.25, 0.25), centre + Vec3(0.25, 0.25, 0.25)), turn, centre),
                 file.path());
  const std::filesystem::path path(file.path());
  const GasSettings s =
      GasConfig(YAML::Load(caseWithStl(path.filename().string())), path.parent_path().string()).settings();
  const Primitive& stl = s.geometry.items().at(1).primitive;
  ASSERT_EQ(stl.kind(), Primitive::Kind::Surface);
  EXPECT_NEAR(stl.volume(), 0.125, 1e-6);  // binary STL: corners rounded to single precision
  // Every cell centre of the 20^3 mesh is fluid exactly when it is in the slab or in the turned cube.
  long inside = 0, disagree = 0;
  for (int k = 0; k < 20; ++k)
    for (int j = 0; j < 20; ++j)
      for (int i = 0; i < 20; ++i) {
        const Vec3 x((i + 0.5) / 20, (j + 0.5) / 20, (k + 0.5) / 20);
        const Vec3 local = turn.transpose() * (x - centre);
        const bool inCube = local.cwiseAbs().maxCoeff() < 0.25;
        inside += inCube;
        disagree += s.geometry.isFluid(x) != (inCube || x[2] <= 0.1);
      }
  EXPECT_EQ(disagree, 0);
  EXPECT_GT(inside, 900);  // about 0.125 * 8000 = 1000 centres
}

TEST(CutCellInput, StlShapeInCaseYamlMissingFileNamesTheKey) {
  const std::string folder = std::filesystem::temp_directory_path().string();
  expectConfigError([&] { GasConfig(YAML::Load(caseWithStl("no_such_vessel.stl")), folder); },
                    {"geometry[1].shape.stl.file", folder + "/no_such_vessel.stl", "no such file"});
  expectConfigError([&] { GasConfig(YAML::Load(caseWithStl("a.stl, scale: 2")), folder); },
                    {"geometry[1].shape.stl", "scale"});
}
