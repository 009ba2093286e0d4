// Cut-cell geometry (issue 31, part 1): fluid volumes, open face fractions and walls of the Cartesian
// cells cut by STL surfaces (aligned and rotated boxes, a sphere) and by the `geometry:` primitives
// (tessellated cylinders, cones, booleans), against exact values (fluid centroids also through their
// first moments against the solid's centroid); each cut cell closes; bad STL input stops with a
// ConfigError naming the file and the problem.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <string>

#include "cfd/base/config_error.hpp"
#include "cfd/geometry/cut_cell_geometry.hpp"
#include "cfd/geometry/stl_reader.hpp"
#include "cfd/geometry/surface_from_geometry.hpp"
#include "tests/support/cut_cell_test_surfaces.hpp"

using namespace parcelflow::cfd;
using namespace parcelflow::cfd::test;

namespace {


double totalFluidVolume(const CutCellGeometry& g) {
  double v = 0;
  for (long c = 0; c < g.background().size(); ++c) v += g.fluidFraction(c) * g.background().cellVolume();
  return v;
}

double faceArea(const CartesianBackground& b, int axis) {
  return b.spacing()[(axis + 1) % 3] * b.spacing()[(axis + 2) % 3];
}

// Every cut cell is a closed polyhedron: open face area vectors + wall area vector = 0. Returns the
// largest |sum| relative to the largest face area.
double largestClosureError(const CutCellGeometry& g) {
  const auto& b = g.background();
  const double largestFace = std::max({faceArea(b, 0), faceArea(b, 1), faceArea(b, 2)});
  double worst = 0;
  for (long c = 0; c < b.size(); ++c) {
    if (!g.isCut(c)) continue;
    Vec3 sum = g.wall(c).areaVector;
    for (int f = 0; f < 6; ++f)
      sum[f / 2] += (f % 2 ? 1.0 : -1.0) * g.openFraction(c, CellFace(f)) * faceArea(b, f / 2);
    worst = std::max(worst, sum.norm() / largestFace);
  }
  return worst;
}

// The centroid of all fluid from the cells' volumes and fluid centroids (first moments); every
// centroid must lie in its cell's box.
Vec3 fluidCentroidOfAll(const CutCellGeometry& g) {
  const auto& b = g.background();
  Vec3 moment = Vec3::Zero();
  double volume = 0;
  for (long c = 0; c < b.size(); ++c) {
    const double v = g.fluidFraction(c) * b.cellVolume();
    const auto ijk = b.ijk(c);
    const Vec3 offset = g.fluidCentroid(c) - b.centre(ijk[0], ijk[1], ijk[2]);
    EXPECT_TRUE((offset.cwiseAbs() - 0.5 * b.spacing()).maxCoeff() <= 1e-15) << "cell " << c;
    moment += v * g.fluidCentroid(c);
    volume += v;
  }
  return moment / volume;
}

double totalWallArea(const CutCellGeometry& g) {
  double a = 0;
  for (long c = 0; c < g.background().size(); ++c)
    if (g.isCut(c)) a += g.wall(c).area;
  return a;
}

// The fluid prism of a regular N-gon inscribed in radius r, height h.
double prismVolume(int n, double r, double h) { return 0.5 * n * r * r * std::sin(2 * M_PI / n) * h; }

void expectClosedAndConsistent(const CutCellGeometry& g) {
  EXPECT_LT(largestClosureError(g), 1e-12);
  EXPECT_LT(g.statistics().maxClosureError, 1e-12);
  EXPECT_LT(g.statistics().maxSharedFaceMismatch, 1e-12);
}

const CartesianBackground unitCube(Vec3(0, 0, 0), Vec3(1, 1, 1), {4, 4, 4});  // 0.25 m cells

// Box [0.25, 0.625] x [0.125, 0.75] x [0, 1]: x = 0.25 is a grid plane inside the background (a wall
// lying on cell faces), x = 0.625 and y = 0.125 halve cells, z = 0 and 1 are the background's sides.
void checkAlignedBox(const CutCellGeometry& g) {
  const auto& b = g.background();
  EXPECT_NEAR(totalFluidVolume(g), 0.375 * 0.625, 1e-12 * 0.234375);
  const long half = b.index(2, 1, 1);  // x in [0.5, 0.75]: fluid up to 0.625
  EXPECT_DOUBLE_EQ(g.fluidFraction(half), 0.5);
  EXPECT_EQ(g.openFraction(half, XMin), 1.0);
  EXPECT_EQ(g.openFraction(half, XMax), 0.0);
  for (CellFace f : {YMin, YMax, ZMin, ZMax}) EXPECT_DOUBLE_EQ(g.openFraction(half, f), 0.5) << f;
  ASSERT_TRUE(g.isCut(half));
  EXPECT_DOUBLE_EQ(g.wall(half).area, 0.0625);
  EXPECT_LT((g.wall(half).normal() - Vec3(1, 0, 0)).norm(), 1e-15);
  EXPECT_LT((g.wall(half).centroid - Vec3(0.625, 0.375, 0.375)).norm(), 1e-15);
  EXPECT_LT((g.fluidCentroid(half) - Vec3(0.5625, 0.375, 0.375)).norm(), 1e-15);
  EXPECT_LT((g.openCentroid(half, YMin) - Vec3(0.5625, 0.25, 0.375)).norm(), 1e-15);
  EXPECT_LT((g.openCentroid(half, XMin) - Vec3(0.5, 0.375, 0.375)).norm(), 1e-15);  // whole face
  const long corner = b.index(2, 0, 1);  // halved in x and in y
  EXPECT_DOUBLE_EQ(g.fluidFraction(corner), 0.25);
  EXPECT_DOUBLE_EQ(g.openFraction(corner, ZMin), 0.25);
  EXPECT_DOUBLE_EQ(g.openFraction(corner, XMin), 0.5);
  EXPECT_DOUBLE_EQ(g.openFraction(corner, YMax), 0.5);
  EXPECT_LT((g.fluidCentroid(corner) - Vec3(0.5625, 0.1875, 0.375)).norm(), 1e-15);
  EXPECT_LT((fluidCentroidOfAll(g) - Vec3(0.4375, 0.4375, 0.5)).norm(), 1e-12);
  // The wall on the grid plane x = 0.25: a wall of the fluid cell, closed for the solid one beyond.
  const long behindWall = b.index(1, 1, 1), solid = b.index(0, 1, 1);
  EXPECT_EQ(g.fluidFraction(behindWall), 1.0);
  EXPECT_EQ(g.openFraction(behindWall, XMin), 0.0);
  EXPECT_EQ(g.openFraction(solid, XMax), 0.0);
  EXPECT_EQ(g.fluidFraction(solid), 0.0);
  ASSERT_TRUE(g.isCut(behindWall));
  EXPECT_DOUBLE_EQ(g.wall(behindWall).area, 0.0625);
  EXPECT_LT((g.wall(behindWall).normal() - Vec3(-1, 0, 0)).norm(), 1e-15);
  // On the background's sides the surface is the boundary patch's: open, not wall.
  EXPECT_NEAR(g.openFraction(b.index(1, 1, 0), ZMin), 1.0, 1e-15);  // sum of two triangles' areas
  EXPECT_NEAR(g.openFraction(b.index(1, 1, 3), ZMax), 1.0, 1e-15);
  EXPECT_EQ(g.openFraction(b.index(0, 1, 0), ZMin), 0.0);
  // y = 0.75 is a surface plane inside the background: the cells below it have their wall there.
  const long underTop = b.index(1, 2, 1);
  EXPECT_EQ(g.openFraction(underTop, YMax), 0.0);
  EXPECT_DOUBLE_EQ(g.wall(underTop).area, 0.125);  // and x = 0.25
  EXPECT_LT((g.wall(underTop).areaVector - Vec3(-0.0625, 0.0625, 0)).norm(), 1e-16);
  expectClosedAndConsistent(g);
}

}  // namespace

TEST(CutCellGeometry, AlignedBoxStlAsciiAndBinary) {
  const TriangleSurface box = boxSurface(Vec3(0.25, 0.125, 0), Vec3(0.625, 0.75, 1));
  const TempFile ascii("box_ascii.stl"), binary("box_binary.stl");
  writeAsciiStl(box, ascii.path());
  writeBinaryStl(box, binary.path());  // every coordinate is a float: the binary file is exact too
  checkAlignedBox(CutCellGeometry(readStlSurface(ascii.path(), "geometry.stl"), unitCube, ascii.path()));
  checkAlignedBox(CutCellGeometry(readStlSurface(binary.path(), "geometry.stl"), unitCube, binary.path()));
}

TEST(CutCellGeometry, RotatedBoxStl) {
  const Eigen::Matrix3d rotation =
      (Eigen::AngleAxisd(0.3, Vec3::UnitZ()) * Eigen::AngleAxisd(0.7, Vec3(1, 1, 0).normalized())).toRotationMatrix();
  const TriangleSurface box =
      transformed(boxSurface(Vec3(0.35, 0.3, 0.25), Vec3(0.65, 0.7, 0.75)), rotation, Vec3(0.5, 0.5, 0.5));
  const TempFile file("rotated_box.stl");
  writeAsciiStl(box, file.path());
  const TriangleSurface read = readStlSurface(file.path(), "geometry.stl");
  const CartesianBackground grid(Vec3(0, 0, 0), Vec3(1, 1, 1), {9, 8, 7});
  const CutCellGeometry g(read, grid, file.path());
  EXPECT_NEAR(totalFluidVolume(g), 0.3 * 0.4 * 0.5, 1e-12 * 0.06);
  EXPECT_NEAR(totalWallArea(g), 2 * (0.3 * 0.4 + 0.4 * 0.5 + 0.3 * 0.5), 1e-12);
  EXPECT_LT((fluidCentroidOfAll(g) - Vec3(0.5, 0.5, 0.5)).norm(), 1e-12);  // the rotation's centre
  expectClosedAndConsistent(g);
}

TEST(CutCellGeometry, SphereWallAreaIsTheSurfaceArea) {
  const TriangleSurface sphere = sphereSurface(Vec3(0.51, 0.49, 0.503), 0.3, 4);  // 5120 triangles
  ASSERT_GT(sphere.volume(), 0);
  const TempFile file("sphere.stl");
  writeAsciiStl(sphere, file.path());
  const TriangleSurface read = readStlSurface(file.path(), "geometry.stl");
  const CartesianBackground grid(Vec3(0, 0, 0), Vec3(1, 1, 1), {16, 16, 16});
  const CutCellGeometry g(read, grid, file.path());
  EXPECT_NEAR(totalWallArea(g), read.area(), 1e-10 * read.area());
  EXPECT_NEAR(totalFluidVolume(g), read.volume(), 1e-10 * read.volume());
  // The icosphere is symmetric about its centre, so its centroid is the centre.
  EXPECT_LT((fluidCentroidOfAll(g) - Vec3(0.51, 0.49, 0.503)).norm(), 1e-12);
  expectClosedAndConsistent(g);
  std::printf("sphere: %ld cut cells of %ld, %.3f s\n", g.statistics().cutCells, grid.size(), g.statistics().seconds);
}

// A slice of the FCC column of cases/psri_fcc_bubbling_bed: radius 0.45 m, 20 x 20 cells of 45 mm.
TEST(CutCellGeometry, TessellatedCylinderOfTheFccColumn) {
  const int segments = defaultCircleSegments;
  const double radius = 0.45, height = 0.225;
  const CartesianBackground grid(Vec3(-0.45, -0.45, 0), Vec3(0.9, 0.9, height), {20, 20, 5});
  const Geometry column({{Geometry::Op::Union, Primitive::cylinder(0, 0, radius, 0, height), ""}});
  const CutCellGeometry g(surfaceOfGeometry(column, grid, segments), grid, "geometry");
  const double prism = prismVolume(segments, radius, height), exact = M_PI * radius * radius * height;
  EXPECT_NEAR(totalFluidVolume(g), prism, 1e-10 * prism);
  EXPECT_NEAR(totalFluidVolume(g), exact, 1e-3 * exact);
  // Every horizontal plane of faces is open over exactly the polygon.
  for (int k = 0; k <= 5; ++k) {
    double open = 0;
    for (int j = 0; j < 20; ++j)
      for (int i = 0; i < 20; ++i)
        open += (k < 5 ? g.openFraction(grid.index(i, j, k), ZMin) : g.openFraction(grid.index(i, j, 4), ZMax)) *
                faceArea(grid, 2);
    EXPECT_NEAR(open, prism / height, 1e-10 * prism / height) << "plane " << k;
  }
  EXPECT_NEAR(totalWallArea(g), segments * 2 * radius * std::sin(M_PI / segments) * height, 1e-10);
  expectClosedAndConsistent(g);
  std::printf("column %d segments: fluid volume %.15g, tessellated prism %.15g, pi R^2 H %.15g "
              "(relative %.3e); %ld cut cells, %.3f s\n",
              segments, totalFluidVolume(g), prism, exact, totalFluidVolume(g) / exact - 1, g.statistics().cutCells,
              g.statistics().seconds);
}

TEST(CutCellGeometry, ConeAndCutOut) {
  const int segments = 48;
  const CartesianBackground grid(Vec3(0, 0, 0), Vec3(1, 1, 1), {8, 8, 8});
  // A frustum (r 0.4 at z 0.1 to r 0.2 at z 0.9) with a cylinder of r 0.1 cut out along its axis.
  const Geometry shape({{Geometry::Op::Union, Primitive::cone(0.5, 0.5, 0.4, 0.2, 0.1, 0.9), ""},
                        {Geometry::Op::Cut, Primitive::cylinder(0.5, 0.5, 0.1, 0.0, 1.0), ""}});
  const CutCellGeometry g(surfaceOfGeometry(shape, grid, segments), grid, "geometry");
  const double polygonFactor = 0.5 * segments * std::sin(2 * M_PI / segments);  // polygon area / r^2
  const double frustum = polygonFactor * 0.8 * (0.16 + 0.08 + 0.04) / 3;
  const double expected = frustum - polygonFactor * 0.01 * 0.8;
  EXPECT_NEAR(totalFluidVolume(g), expected, 1e-10 * expected);
  expectClosedAndConsistent(g);
}

TEST(CutCellGeometry, EmptyGeometryIsTheWholeBox) {
  const CutCellGeometry g(surfaceOfGeometry(Geometry(), unitCube), unitCube, "geometry");
  EXPECT_NEAR(totalFluidVolume(g), 1.0, 1e-14);
  for (long c = 0; c < unitCube.size(); ++c)
    for (int f = 0; f < 6; ++f) EXPECT_EQ(g.openFraction(c, CellFace(f)), 1.0);
}
