// The cut-cell geometry of the FCC column of cases/psri_fcc_bubbling_bed (its mesh and geometry keys):
// 20 x 20 x 167 cells, the 0.45 m column to z = 7 m and the 0.1 m exit tube above, tessellated with
// defaultCircleSegments. Checks the fluid volume against the tessellated and the round column and
// prints the time it takes (the number in cfd/README.md, "Cut-cell geometry").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cfd/geometry/cut_cell_geometry.hpp"
#include "cfd/geometry/surface_from_geometry.hpp"

using namespace parcelflow::cfd;

TEST(CutCellFccColumn, VolumeAndTime) {
  const double top = 7.493589743589744;  // 7.0 x 167 / 156: the lid on a cell face
  const CartesianBackground grid(Vec3(-0.45, -0.45, 0.0), Vec3(0.9, 0.9, top), {20, 20, 167});
  const Geometry column({{Geometry::Op::Union, Primitive::cylinder(0, 0, 0.45, 0.0, 7.0), ""},
                         {Geometry::Op::Union, Primitive::cylinder(0, 0, 0.1, 7.0, top), ""}});
  const int n = defaultCircleSegments;
  const TriangleSurface surface = surfaceOfGeometry(column, grid, n);
  const CutCellGeometry g(surface, grid, "geometry");
  const double polygon = 0.5 * n * std::sin(2 * M_PI / n);  // polygon area / r^2
  const double tessellated = polygon * (0.45 * 0.45 * 7.0 + 0.1 * 0.1 * (top - 7.0));
  const double round = M_PI * (0.45 * 0.45 * 7.0 + 0.1 * 0.1 * (top - 7.0));
  const auto& st = g.statistics();
  EXPECT_NEAR(st.fluidVolume, tessellated, 1e-10 * tessellated);
  EXPECT_NEAR(st.fluidVolume, round, 1e-3 * round);
  EXPECT_LT(st.maxClosureError, 1e-12);
  EXPECT_LT(st.maxSharedFaceMismatch, 1e-12);
  std::printf("FCC column, %d segments, %zu surface triangles: %ld fluid, %ld cut, %ld solid cells; fluid volume "
              "%.12g m3 (tessellated %.12g, relative %.2e; round %.12g, relative %.2e); wall area %.6g m2; "
              "closure %.2e, shared faces %.2e; %.2f s\n",
              n, surface.triangles.size(), st.fluidCells, st.cutCells, st.solidCells, st.fluidVolume, tessellated,
              st.fluidVolume / tessellated - 1, round, st.fluidVolume / round - 1, st.wallArea, st.maxClosureError,
              st.maxSharedFaceMismatch, st.seconds);
}
