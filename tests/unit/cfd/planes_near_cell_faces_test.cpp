// planesNearCellFaces (cfd/mesh/planes_near_cell_faces.hpp): the full FCC case's lid 4e-8 m above a cell face is named
// with its distance; on the face (the case's height since 2026-12-07), in the middle of a cell or further than
// small_cell_fraction of a cell it is not; a box's planes along every axis are checked.
#include <gtest/gtest.h>

#include "cfd/mesh/planes_near_cell_faces.hpp"

using namespace parcelflow::cfd;

namespace {

MeshSettings fccMesh(double height) {
  MeshSettings m;
  m.origin = Vec3(-0.45, -0.45, 0.0);
  m.lengths = Vec3(0.9, 0.9, height);
  m.cells = {20, 20, 167};
  m.walls = WallRepresentation::CutCells;
  return m;
}

Geometry fccColumn(double height) {
  return Geometry({{Geometry::Op::Union, Primitive::cylinder(0, 0, 0.45, 0.0, 7.0), ""},
                   {Geometry::Op::Union, Primitive::cylinder(0, 0, 0.1, 7.0, height), ""}});
}

}  // namespace

TEST(PlanesNearCellFaces, NamesTheFccLidAHairAboveACellFace) {
  const auto found = planesNearCellFaces(fccMesh(7.4935897), fccColumn(7.4935897));
  ASSERT_EQ(found.size(), 2u);  // the column's top and the tube's foot, both at z = 7
  EXPECT_NE(found[0].find("geometry item 1: its plane z = 7 lies 4.07e-08 m off the cell face at 6.99999995"),
            std::string::npos) << found[0];
  EXPECT_NE(found[1].find("geometry item 2: its plane z = 7"), std::string::npos) << found[1];
}

TEST(PlanesNearCellFaces, APlaneOnAFaceOrInsideACellIsNotNamed) {
  EXPECT_TRUE(planesNearCellFaces(fccMesh(7.493589743589744), fccColumn(7.493589743589744)).empty());
  // the lid half a cell above a face, and 0.02 of a cell above one (more than small_cell_fraction 0.01)
  const double h = 7.4935897 / 167;
  EXPECT_TRUE(planesNearCellFaces(fccMesh(7.0 * 167 / 155.5), fccColumn(7.0 * 167 / 155.5)).empty());
  MeshSettings m = fccMesh(7.4935897);
  m.origin[2] = -(7.0 - 156 * h) - 0.02 * h;  // the face 0.02 h below the lid
  EXPECT_TRUE(planesNearCellFaces(m, fccColumn(7.4935897)).empty());
  m.smallCellFraction = 0.05;  // within that share: named, the column's ends, the tube's foot and top alike
  EXPECT_EQ(planesNearCellFaces(m, fccColumn(7.4935897)).size(), 4u);
}

TEST(PlanesNearCellFaces, ChecksABoxAlongEveryAxis) {
  MeshSettings m;
  m.lengths = Vec3(1.0, 1.0, 1.0);
  m.cells = {10, 10, 10};
  // x planes on faces, y = 0.3 + 1e-6 a hair off one, z planes in the middle of cells
  const Geometry box({{Geometry::Op::Union, Primitive::box(Vec3(0.2, 0.3 + 1e-6, 0.15), Vec3(0.8, 0.7, 0.85)), ""}});
  const auto found = planesNearCellFaces(m, box);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NE(found[0].find("its plane y = 0.300001 lies 1e-06 m off the cell face at 0.3"), std::string::npos)
      << found[0];
}
