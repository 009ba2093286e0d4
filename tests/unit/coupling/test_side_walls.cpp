// sideWallAreaPerVolume on a 0.3 x 0.2 x 0.5 m box of 0.1 m cells, walls at x and y, inlet and outlet at z:
// 2 / 0.3 + 2 / 0.2 per metre with gravity along -z; faces normal to an axis that is periodic for the parcels
// and faces across gravity do not count. Any number of ranks. narrowestExtentBetweenWalls: the smallest
// length along an axis that is not periodic for the parcels.
#include <gtest/gtest.h>
#include <mpi.h>

#include <array>
#include <cmath>

#include "tests/unit/coupling/box_mesh.hpp"
#include "coupling/run/side_walls.h"

using namespace parcelflow;

namespace {
using coupling::test::boxMesh;

std::vector<cfd::BoundarySettings> boundaries(cfd::BoundaryType sides) {
  std::vector<cfd::BoundarySettings> b;
  for (const char* side : {"xmin", "xmax", "ymin", "ymax"}) b.push_back({side, sides});
  b.push_back({"zmin", cfd::BoundaryType::VelocityInlet});
  b.push_back({"zmax", cfd::BoundaryType::PressureOutlet});
  return b;
}
}  // namespace

TEST(SideWalls, AreaPerVolumeOfTheSideWalls) {
  const cfd::Mesh mesh = boxMesh();
  const cfd::Vec3 down(0.0, 0.0, -9.81);
  const auto walls = boundaries(cfd::BoundaryType::NoSlipWall);
  EXPECT_NEAR(coupling::sideWallAreaPerVolume(mesh, walls, down, {false, false, false}), 2 / 0.3 + 2 / 0.2, 1e-9);
  // free-slip walls count as well: the parcels pack against them all the same
  EXPECT_NEAR(coupling::sideWallAreaPerVolume(mesh, boundaries(cfd::BoundaryType::FreeSlipWall), down,
                                              {false, false, false}),
              2 / 0.3 + 2 / 0.2, 1e-9);
  // periodic along y for the parcels: only the x walls
  EXPECT_NEAR(coupling::sideWallAreaPerVolume(mesh, walls, down, {false, true, false}), 2 / 0.3, 1e-9);
  // gravity along x: the x walls are floor and roof, z is inlet and outlet, the y walls remain
  EXPECT_NEAR(coupling::sideWallAreaPerVolume(mesh, walls, cfd::Vec3(-9.81, 0.0, 0.0), {false, false, false}),
              2 / 0.2, 1e-9);
}

// The Goldschmidt bed's box (0.15 x 0.015 x 0.3 m): its depth between walls, its width once the depth is periodic
// for the parcels, nothing when every axis is.
TEST(SideWalls, NarrowestExtentBetweenWalls) {
  const std::array<double, 3> box{0.15, 0.015, 0.3};
  EXPECT_EQ(coupling::narrowestExtentBetweenWalls(box, {false, false, false}), 0.015);
  EXPECT_EQ(coupling::narrowestExtentBetweenWalls(box, {false, true, false}), 0.15);
  EXPECT_EQ(coupling::narrowestExtentBetweenWalls(box, {true, true, false}), 0.3);
  EXPECT_TRUE(std::isinf(coupling::narrowestExtentBetweenWalls(box, {true, true, true})));
}
