// PlaneAverages on a 3 x 2 x 5 box of 0.1 m cells: a pressure linear in z, p = 1000 - 50 z, with its
// gradient, is recovered exactly at any height (also at the plate, z = 0, half a cell below the first
// centre); without the gradient the plane gets its layer's mean. Any number of ranks.
#include <gtest/gtest.h>
#include <mpi.h>

#include "cfd/base/config_error.hpp"
#include "tests/unit/coupling/box_mesh.hpp"
#include "coupling/monitors/plane_averages.h"

using namespace parcelflow;

namespace {
using coupling::test::boxMesh;
}  // namespace

TEST(PlaneAverages, LinearFieldIsExactAtTheRequestedHeights) {
  const cfd::Mesh mesh = boxMesh();
  const coupling::PlaneAverages planes(mesh, {0.0, 0.13, 0.25, 0.4999}, "monitors.pressure_planes");
  cfd::ScalarField p(mesh.nLocalCells());
  cfd::VectorField grad(mesh.nLocalCells(), cfd::Vec3(0.0, 0.0, -50.0));
  for (int c = 0; c < mesh.nLocalCells(); ++c) p[c] = 1000.0 - 50.0 * mesh.cellCentre(c)[2];
  const std::vector<double> exact = planes.meansAtHeights(p, grad);
  EXPECT_NEAR(exact[0], 1000.0, 1e-10);
  EXPECT_NEAR(exact[1], 1000.0 - 50.0 * 0.13, 1e-10);
  EXPECT_NEAR(exact[2], 1000.0 - 50.0 * 0.25, 1e-10);
  EXPECT_NEAR(exact[3], 1000.0 - 50.0 * 0.4999, 1e-10);
  const std::vector<double> layer = planes.means(p);
  EXPECT_NEAR(layer[0], 1000.0 - 50.0 * 0.05, 1e-10);  // the first layer's centre
  EXPECT_NEAR(layer[1], 1000.0 - 50.0 * 0.15, 1e-10);
  EXPECT_NEAR(planes.layerArea(0), 0.06, 1e-14);
}

TEST(PlaneAverages, HeightOutsideTheMeshNamesTheKey) {
  const cfd::Mesh mesh = boxMesh();
  try {
    coupling::PlaneAverages planes(mesh, {0.7}, "monitors.pressure_planes");
    FAIL() << "no error for a height above the mesh";
  } catch (const cfd::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("monitors.pressure_planes: height 0.7"), std::string::npos) << e.what();
  }
}
