// Kernel weights: sum to 1 everywhere (walls, inside corner), symmetry, the analytic separable
// Gaussian, the bias of gathering a linear field, truncated mass, orphans/fallbacks, selection by name.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <random>
#include <set>

#include "tests/support/ghost_deposition_oracle.hpp"
#include "tests/unit/transfer/test_grid.hpp"
#include "coupling/transfer/transfer_kernel.hpp"
#include "cfd/base/config_error.hpp"
#include "cfd/base/internal_error.hpp"

using namespace parcelflow::coupling;
using namespace parcelflow::coupling::test;

namespace {

// the test grid's cell lengths (test_grid.hpp), for the kernel with one length scale
const double kTestSpacing[3] = {0.01, 0.02, 0.015};

std::vector<TransferKernel> allKernels() {
  return {GaussianKernel(1.0, 1), GaussianKernel(1.0, 2), GaussianKernel(1.0, 3), GaussianKernel(2.0, 2),
          GaussianKernel(0.5, 3), GaussianKernel(1.0, 4), GaussianKernel(1.0, 2, kTestSpacing), CentroidKernel(1)};
}

std::string describe(const TransferKernel& k) {
  if (const auto* g = std::get_if<GaussianKernel>(&k))
    return "gaussian a=" + std::to_string(g->sharpness()) + " R=" + std::to_string(g->radius()) +
           (g->axisSharpness(0) == g->axisSharpness(1) ? "" : " h=cbrt(cell volume)");
  return "centroid";
}

// Random active positions plus hand-picked ones on the outer walls, the box corner and the inside corner.
std::vector<double> testPositions(const MaskedGrid& g) {
  std::vector<double> pos = randomActivePositions(g, 20000, 11);
  const auto& G = g.grid;
  const double x0 = G.origin[0], y0 = G.origin[1], z0 = G.origin[2];
  const double xc = x0 + 6 * G.spacing[0], yc = y0 + 5 * G.spacing[1];  // inside corner edge
  const double special[][3] = {{x0, y0, z0},                                   // box corner
                               {x0 + 1e-12, y0 + 0.05, z0 + 0.06},             // on the x- wall
                               {xc, yc, z0 + 0.05},                            // inside corner
                               {xc - 1e-9, yc - 1e-9, z0 + 0.05},              // just inside the fluid
                               {xc - 0.3 * G.spacing[0], yc + 2.5 * G.spacing[1], z0 + 0.11},
                               {x0 + 0.119999, y0 + 0.099, z0 + 0.1199}};      // far corner of the arm
  for (const auto& s : special) pos.insert(pos.end(), s, s + 3);
  return pos;
}

// A parcel displaced by kOffCentreShift cell lengths (per axis) from the centre of cell kOffCentreCell.
const int kOffCentreCell[3] = {3, 4, 4};
const double kOffCentreShift[3] = {0.3, -0.45, 0.1};

double weightSum(const Stencil& s) {
  double sum = 0.0;
  for (int e = 0; e < s.size; ++e) sum += s.weight[e];
  return sum;
}

// The stencil's weights against exp(-sum_d (dx_d / length_d)^2), computed from the distances between the cell
// centres and the parcel at x and renormalised over the stencil's cells.
void expectGaussianOfDistances(const MaskedGrid& g, const Stencil& s, const double (&x)[3],
                               const double (&length)[3]) {
  std::vector<double> expected(s.size);
  double total = 0.0;
  for (int e = 0; e < s.size; ++e) {
    double exponent = 0.0;
    for (int d = 0; d < 3; ++d) {
      const double t = (g.grid.cellCentre(d, g.ijkOf[s.cell[e]][d]) - x[d]) / length[d];
      exponent += t * t;
    }
    expected[e] = std::exp(-exponent);
    total += expected[e];
  }
  for (int e = 0; e < s.size; ++e) EXPECT_NEAR(s.weight[e], expected[e] / total, 1e-14);
}

void offCentreParcel(const MaskedGrid& g, double (&x)[3]) {
  for (int d = 0; d < 3; ++d)
    x[d] = g.grid.cellCentre(d, kOffCentreCell[d]) + kOffCentreShift[d] * g.grid.spacing[d];
}

// The stencil's weights of the cell_volume Gaussian (h = cbrt of kTestSpacing's cell) against the Gaussian of the
// parcel at x plus, on the cells imageLo..imageHi along x, that of its image mirrored to x = image, computed from
// the distances and renormalised over the stencil's cells.
void expectParcelAndImageAlongX(const MaskedGrid& g, const Stencil& s, const double (&x)[3], double image,
                                int imageLo, int imageHi) {
  const double h = std::cbrt(kTestSpacing[0] * kTestSpacing[1] * kTestSpacing[2]);
  std::vector<double> expected(s.size);
  double total = 0.0;
  for (int e = 0; e < s.size; ++e) {
    double r2 = 0.0;
    for (int d = 1; d < 3; ++d) r2 += std::pow(g.grid.cellCentre(d, g.ijkOf[s.cell[e]][d]) - x[d], 2);
    const int ix = g.ijkOf[s.cell[e]][0];
    const double cx = g.grid.cellCentre(0, ix);
    expected[e] = std::exp(-(r2 + std::pow(cx - x[0], 2)) / (h * h)) +
                  (ix >= imageLo && ix <= imageHi ? std::exp(-(r2 + std::pow(cx - image, 2)) / (h * h)) : 0.0);
    total += expected[e];
  }
  for (int e = 0; e < s.size; ++e) EXPECT_NEAR(s.weight[e], expected[e] / total, 1e-14);
}

}  // namespace

TEST(KernelWeights, SumToOneOnActiveCellsEverywhereIncludingWallsAndInsideCorner) {
  const MaskedGrid g = makeGrid({12, 10, 8}, true);
  const std::vector<double> pos = testPositions(g);
  const std::size_t n = pos.size() / 3;
  for (const TransferKernel& kernel : allKernels()) {
    double worst = 0.0;
    std::size_t clipped = 0;
    int fullSize = 0;
    if (const auto* gk = std::get_if<GaussianKernel>(&kernel)) fullSize = std::pow(2 * gk->radius() + 1, 3);
    const TransferStats st = forEachParcelStencil(kernel, g.grid, g, n, pos.data(), [&](std::size_t p, const Stencil& s) {
      double sum = 0.0;
      std::set<int> seen;
      for (int m = 0; m < s.size; ++m) {
        ASSERT_GE(s.cell[m], 0);
        ASSERT_LT(s.cell[m], g.localSize);
        ASSERT_GE(g.ijkOf[s.cell[m]][0], 0) << "gap index returned";
        ASSERT_GE(s.weight[m], 0.0);
        ASSERT_TRUE(seen.insert(s.cell[m]).second) << "cell twice in a stencil";
        sum += s.weight[m];
      }
      worst = std::max(worst, std::abs(sum - 1.0));
      if (s.size < fullSize) ++clipped;
      EXPECT_LE(std::abs(sum - 1.0), 1e-14) << describe(kernel) << " parcel " << p;
    });
    EXPECT_EQ(st.parcels, n);
    EXPECT_EQ(st.orphans, 0u) << describe(kernel);
    // only the point exactly on the inside corner edge lies in a solid cell (floor picks the block)
    EXPECT_EQ(st.fallbacks, std::holds_alternative<CentroidKernel>(kernel) ? 1u : 0u) << describe(kernel);
    if (fullSize > 0) {
      EXPECT_GT(clipped, 1000u);  // renormalisation at walls really exercised
    }
    std::printf("[measured] %-22s max |sum w - 1| = %.2e over %zu parcels (%zu with wall-clipped stencils)\n",
                describe(kernel).c_str(), worst, n, clipped);
  }
}

TEST(KernelWeights, GaussianAtCellCentreIsSymmetricAndEqualsAnalyticSeparableForm) {
  const MaskedGrid g = makeGrid({12, 10, 8}, true);
  const int c0[3] = {3, 4, 4};  // stencil +-2 fully active
  const double x[3] = {g.grid.cellCentre(0, c0[0]), g.grid.cellCentre(1, c0[1]), g.grid.cellCentre(2, c0[2])};
  for (double a : {1.0, 0.7}) {
    const GaussianKernel k(a, 2);
    Stencil s;
    ASSERT_EQ(stencilOf(k, g.grid, x, g, s), StencilResult::ok);
    ASSERT_EQ(s.size, 125);
    double z = 0.0;
    for (int m = -2; m <= 2; ++m) z += std::exp(-a * m * m);
    std::map<std::array<int, 3>, double> w;
    for (int m = 0; m < s.size; ++m) {
      const auto ijk = g.ijkOf[s.cell[m]];
      w[{ijk[0] - c0[0], ijk[1] - c0[1], ijk[2] - c0[2]}] = s.weight[m];
    }
    for (const auto& [o, wt] : w) {
      const double analytic = std::exp(-a * (o[0] * o[0] + o[1] * o[1] + o[2] * o[2])) / (z * z * z);
      // (the parcel's position in cell units carries ~1e-15 rounding, hence 1e-15 and not ==)
      EXPECT_NEAR(wt, analytic, 1e-15) << o[0] << o[1] << o[2];
      EXPECT_NEAR(wt, (w[{-o[0], o[1], o[2]}]), 1e-15) << "mirror x";
      EXPECT_NEAR(wt, (w[{o[0], -o[1], o[2]}]), 1e-15) << "mirror y";
      EXPECT_NEAR(wt, (w[{o[0], o[1], -o[2]}]), 1e-15) << "mirror z";
      EXPECT_NEAR(wt, (w[{o[1], o[0], o[2]}]), 1e-15) << "swap x,y (weights in cell units)";
    }
  }
}

TEST(KernelWeights, GaussianOffCentreUsesCellUnitsPerAxis) {
  // parcel displaced by t = (0.3, -0.45, 0.1) cell lengths from the centre of cell (3, 4, 4) on the
  // anisotropic grid (hx = 0.01, hy = 0.02, hz = 0.015): w = prod_d exp(-a (m_d - t_d)^2) / Z_d
  const MaskedGrid g = makeGrid({12, 10, 8}, true);
  const int* c0 = kOffCentreCell;
  const double* t = kOffCentreShift;
  double x[3];
  offCentreParcel(g, x);
  const double a = 1.0;
  double z[3] = {0, 0, 0};
  for (int d = 0; d < 3; ++d)
    for (int m = -2; m <= 2; ++m) z[d] += std::exp(-a * (m - t[d]) * (m - t[d]));
  Stencil s;
  ASSERT_EQ(stencilOf(GaussianKernel(a, 2), g.grid, x, g, s), StencilResult::ok);
  ASSERT_EQ(s.size, 125);
  for (int e = 0; e < s.size; ++e) {
    double w = 1.0;
    for (int d = 0; d < 3; ++d) {
      const int m = g.ijkOf[s.cell[e]][d] - c0[d];
      w *= std::exp(-a * (m - t[d]) * (m - t[d])) / z[d];
    }
    EXPECT_NEAR(s.weight[e], w, 1e-15);
  }
}

TEST(KernelWeights, GaussianWithTheCellVolumeLengthIsIsotropicInSpace) {
  // h = (hx hy hz)^(1/3) (paper eq. 8, "a characteristic length scale of the cell"): on the anisotropic grid
  // (hx = 0.01, hy = 0.02, hz = 0.015) each weight is exp(-a |x_cell - x_p|^2 / h^2) in metres, renormalised
  // over the 5 x 5 x 5 window, computed here from the distances directly.
  const MaskedGrid g = makeGrid({12, 10, 8}, true);
  double x[3];
  offCentreParcel(g, x);
  const double a = 1.0;
  const double spacing[3] = {g.grid.spacing[0], g.grid.spacing[1], g.grid.spacing[2]};
  const double h = std::cbrt(spacing[0] * spacing[1] * spacing[2]);
  Stencil s;
  const GaussianKernel kernel(a, 2, spacing);
  ASSERT_EQ(stencilOf(kernel, g.grid, x, g, s), StencilResult::ok);
  ASSERT_EQ(s.size, 125);
  const double length = h / std::sqrt(a);  // exp(-a r^2 / h^2)
  expectGaussianOfDistances(g, s, x, {length, length, length});
  // per axis in that axis' cell lengths: a (h_d / h)^2, narrower along the longest axis
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(kernel.axisSharpness(d), a * spacing[d] * spacing[d] / (h * h), 1e-14);
  // on cubic cells it is the per-axis kernel exactly
  const double cube[3] = {0.004, 0.004, 0.004};
  for (int d = 0; d < 3; ++d) EXPECT_EQ(GaussianKernel(a, 2, cube).axisSharpness(d), a);
}

TEST(KernelWeights, GaussianOfAParcelWiderThanTheCellFollowsTheParcel) {
  // parcel_scale lambda: a parcel of collision diameter D with lambda D > h is spread as exp(-a |dx|^2 /
  // (lambda D)^2) over a window of ceil(R lambda D / h) cells per side, computed here from the distances.
  const MaskedGrid g = makeGrid({24, 20, 16}, false);
  double x[3];
  offCentreParcel(g, x);
  const double a = 1.0, lambda = 1.0;
  const double h = std::cbrt(kTestSpacing[0] * kTestSpacing[1] * kTestSpacing[2]);  // 14.4 mm
  const GaussianKernel kernel(a, 2, kTestSpacing, true, lambda);
  const double D = 0.02;  // h_p / h = 1.39: R_p = ceil(2.77) = 3
  Stencil s;
  ASSERT_EQ(stencilOf(kernel, g.grid, x, g, s, D), StencilResult::ok);
  ASSERT_EQ(s.size, 7 * 7 * 7);
  const double length = lambda * D / std::sqrt(a);  // exp(-a r^2 / (lambda D)^2)
  expectGaussianOfDistances(g, s, x, {length, length, length});

  // a parcel with lambda D <= h, and any parcel with lambda = 0, gets the cell's kernel exactly
  Stencil cell, small, off;
  ASSERT_EQ(stencilOf(GaussianKernel(a, 2, kTestSpacing), g.grid, x, g, cell), StencilResult::ok);
  ASSERT_EQ(stencilOf(kernel, g.grid, x, g, small, 0.99 * h / lambda), StencilResult::ok);
  ASSERT_EQ(stencilOf(GaussianKernel(a, 2, kTestSpacing, true, 0.0), g.grid, x, g, off, D), StencilResult::ok);
  ASSERT_EQ(small.size, cell.size);
  ASSERT_EQ(off.size, cell.size);
  for (int e = 0; e < cell.size; ++e) {
    EXPECT_EQ(small.weight[e], cell.weight[e]);
    EXPECT_EQ(off.weight[e], cell.weight[e]);
  }
}

TEST(KernelWeights, CellAxesKernelWidensOnlyTheAxesNarrowerThanTheParcel) {
  // length_scale cell_axes: h_d = the cell length per axis (10, 20, 15 mm). A 15 mm parcel widens x only
  // (to 15 mm, window +-3), and leaves y (20 mm) and z (15 mm, not wider) as they were.
  const MaskedGrid g = makeGrid({24, 20, 16}, false);
  double x[3];
  offCentreParcel(g, x);
  const double D = 0.015;
  Stencil s;
  ASSERT_EQ(stencilOf(GaussianKernel(1.0, 2, kTestSpacing, false, 1.0), g.grid, x, g, s, D), StencilResult::ok);
  ASSERT_EQ(s.size, 7 * 5 * 5);
  expectGaussianOfDistances(g, s, x, {D, kTestSpacing[1], kTestSpacing[2]});
}

TEST(KernelWeights, ParcelWindowIsCappedAtTheLargestRadius) {
  // lambda D = 4 h would need +-8 cells; the window stops at maxRadius = 4 (9 cells), still summing to 1.
  const MaskedGrid g = makeGrid({24, 20, 16}, false);
  double x[3];
  for (int d = 0; d < 3; ++d) x[d] = g.grid.cellCentre(d, 8) + kOffCentreShift[d] * g.grid.spacing[d];
  const double h = std::cbrt(kTestSpacing[0] * kTestSpacing[1] * kTestSpacing[2]);
  Stencil s;
  ASSERT_EQ(stencilOf(GaussianKernel(1.0, 2, kTestSpacing, true, 1.0), g.grid, x, g, s, 4.0 * h), StencilResult::ok);
  EXPECT_EQ(s.size, 9 * 9 * 9);
  EXPECT_NEAR(weightSum(s), 1.0, 1e-14);
}

TEST(KernelWeights, ReflectingFacesAddTheMirrorImagesWeights) {
  // boundary: reflect. A parcel 0.3 cells above the lower x face: each cell's weight is the Gaussian of the
  // parcel plus that of its image mirrored at the face, computed here from the distances; in the interior
  // (no cell of the window beyond a face) the weights are those of the truncating kernel exactly.
  const MaskedGrid g = makeGrid({24, 20, 16}, false);
  const GaussianKernel reflecting(1.0, 2, kTestSpacing, true, 0.0, true), truncating(1.0, 2, kTestSpacing);
  double x[3];
  offCentreParcel(g, x);
  Stencil inner, innerTruncated;
  ASSERT_EQ(stencilOf(reflecting, g.grid, x, g, inner), StencilResult::ok);
  ASSERT_EQ(stencilOf(truncating, g.grid, x, g, innerTruncated), StencilResult::ok);
  ASSERT_EQ(inner.size, innerTruncated.size);
  for (int e = 0; e < inner.size; ++e) EXPECT_EQ(inner.weight[e], innerTruncated.weight[e]);

  x[0] = g.grid.origin[0] + 0.3 * g.grid.spacing[0];
  const double image = 2.0 * g.grid.origin[0] - x[0];
  Stencil s;
  ASSERT_EQ(stencilOf(reflecting, g.grid, x, g, s), StencilResult::ok);
  ASSERT_EQ(s.size, 3 * 5 * 5);  // cells 0..2 in x: cells -1 and -2 folded onto 0 and 1
  // the window is +-2 cells around cell 0: its cells -1 and -2 are the images of cells 0 and 1
  expectParcelAndImageAlongX(g, s, x, image, 0, 1);
}

TEST(KernelWeights, ReflectingWallsInsideTheBoxAddTheMirrorImagesWeights) {
  // The L-shaped mask's cut-out block (i >= 6 for j >= 5) is a wall inside the box. A parcel 0.3 cells left of
  // its face x = 6 in a row that meets it: the cells beyond the face (i = 6, 7) fold onto their mirror cells
  // (5, 4), as the image parcel behind the face puts them; the window stops at the face. Along y the parcel's
  // row (i = 5) is fluid throughout, so y stays the Gaussian.
  const MaskedGrid g = makeGrid({12, 10, 8}, true);
  const GaussianKernel reflecting(1.0, 2, kTestSpacing, true, 0.0, true);
  const double face = g.grid.origin[0] + 6 * g.grid.spacing[0];
  const double x[3] = {face - 0.3 * g.grid.spacing[0], g.grid.cellCentre(1, 7) + 0.2 * g.grid.spacing[1],
                       g.grid.cellCentre(2, 4) - 0.1 * g.grid.spacing[2]};
  const double image = 2.0 * face - x[0];
  Stencil s;
  ASSERT_EQ(stencilOf(reflecting, g.grid, x, g, s), StencilResult::ok);
  ASSERT_EQ(s.size, 3 * 5 * 5);  // cells 3..5 in x
  for (int e = 0; e < s.size; ++e) EXPECT_LE(g.ijkOf[s.cell[e]][0], 5);
  expectParcelAndImageAlongX(g, s, x, image, 4, 5);
}

TEST(KernelWeights, ReflectingFacesFoldAWindowWiderThanTheBox) {
  // 2 cells across, a window of +-4: cells beyond both faces fold back, repeatedly, and the weights
  // still sum to 1 over the 2 cells.
  const MaskedGrid g = makeGrid({24, 2, 16}, false);
  const GaussianKernel kernel(1.0, 4, kTestSpacing, true, 0.0, true);
  double x[3];
  for (int d = 0; d < 3; ++d) x[d] = g.grid.cellCentre(d, d == 1 ? 0 : 8) + 0.2 * g.grid.spacing[d];
  Stencil s;
  ASSERT_EQ(stencilOf(kernel, g.grid, x, g, s), StencilResult::ok);
  EXPECT_EQ(s.size, 9 * 2 * 9);
  EXPECT_NEAR(weightSum(s), 1.0, 1e-14);
}

TEST(KernelWeights, GatherOfLinearFieldInTheInterior) {
  // A linear field f = x (per axis) at cell centres, gathered at the parcel: exact at cell centres by
  // symmetry; elsewhere the truncated lattice Gaussian has a small bias sum w x_c - x_p. It is NOT zero
  // (truncation + the discrete lattice); measured here and predicted per axis by this python3 snippet:
  //   import math
  //   def bias(a, R, t):   # t = parcel offset from its cell centre, cell lengths
  //       ws = [(m - t, math.exp(-a*(m - t)**2)) for m in range(-R, R+1)]
  //       return sum(x*w for x, w in ws)/sum(w for _, w in ws)
  //   max(abs(bias(1, R, -0.5 + i/4000)) for i in range(4000))
  //   -> 9.51e-2 (R = 1), 2.73e-3 (R = 2), 3.27e-4 (R = 3)
  // The centroid kernel returns the cell centre (error <= h/2).
  const MaskedGrid g = makeGrid({16, 16, 16}, false);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> cellX(3 * g.localSize, 0.0);
  for (int c = 0; c < g.localSize; ++c)
    if (g.ijkOf[c][0] >= 0)
      for (int d = 0; d < 3; ++d) cellX[3 * c + d] = g.centre(c, d);
  struct Case {
    TransferKernel k;
    int margin;
    double bound;  // asserted upper bound of max |bias| / h
  };
  const Case cases[] = {{GaussianKernel(1.0, 2), 2, 2.75e-3}, {GaussianKernel(1.0, 3), 3, 3.3e-4},
                        {GaussianKernel(1.0, 1), 1, 9.6e-2}, {CentroidKernel(1), 0, 0.5}};
  for (const Case& c : cases) {
    std::vector<double> pos;
    for (int p = 0; p < 20000; ++p)
      for (int d = 0; d < 3; ++d)
        pos.push_back(g.grid.origin[d] + g.grid.spacing[d] * (c.margin + u(rng) * (16 - 2 * c.margin)));
    for (int i = c.margin; i < 16 - c.margin; ++i)  // plus exact cell centres (full stencil)
      for (int d = 0; d < 3; ++d) pos.push_back(g.grid.cellCentre(d, i));
    const std::size_t n = pos.size() / 3;
    std::vector<double> got(3 * n);
    const TransferStats st = gatherToParcels(c.k, g.grid, g, n, pos.data(), 3, cellX.data(), got.data());
    ASSERT_EQ(st.orphans, 0u);
    double worst = 0.0, worstCentre = 0.0;
    for (std::size_t p = 0; p < n; ++p)
      for (int d = 0; d < 3; ++d) {
        const double e = std::abs(got[3 * p + d] - pos[3 * p + d]) / g.grid.spacing[d];
        (p < 20000 ? worst : worstCentre) = std::max(p < 20000 ? worst : worstCentre, e);
      }
    std::printf("[measured] %-22s linear-field gather: max |bias|/h = %.3e (random), %.1e (at cell centres)\n",
                describe(c.k).c_str(), worst, worstCentre);
    EXPECT_LE(worst, c.bound);
    EXPECT_LE(worstCentre, 1e-12);
  }
}

TEST(KernelWeights, RetainedMassOfTruncatedGaussianMatchesPython) {
  // python3: math.exp sums over m in [-R, R] and [-60, 60] (see /README "truncated mass"):
  //   def retained(a, R, t):
  //       allw = sum(math.exp(-a*(m - t)**2) for m in range(-60, 61))
  //       return sum(math.exp(-a*(m - t)**2) for m in range(-R, R+1))/allw
  EXPECT_NEAR(GaussianKernel::retainedMassFraction1D(1.0, 2, 0.0), 0.99986063436690453, 1e-15);
  EXPECT_NEAR(GaussianKernel::retainedMassFraction1D(1.0, 2, -0.5), 0.99890534340840476, 1e-15);
  EXPECT_NEAR(GaussianKernel::retainedMassFraction1D(1.0, 1, -0.5), 0.93834479191205045, 1e-15);
  EXPECT_NEAR(GaussianKernel::retainedMassFraction1D(1.0, 3, -0.5), 0.99999729819573147, 1e-15);
}

TEST(KernelWeights, OrphansAndFallbacksAreCountedAndListed) {
  const MaskedGrid g = makeGrid({12, 10, 8}, true);
  const auto at = [&](double ci, double cj, double ck) {
    return std::array<double, 3>{g.grid.origin[0] + ci * g.grid.spacing[0], g.grid.origin[1] + cj * g.grid.spacing[1],
                                 g.grid.origin[2] + ck * g.grid.spacing[2]};
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::array<double, 3>> pts = {
      at(3.5, 3.5, 4.5),   // 0: fluid
      at(9.5, 8.5, 4.5),   // 1: deep in the solid block: orphan for R <= 2, centroid orphan (search 1)
      at(6.2, 5.7, 4.5),   // 2: solid cell next to the inside corner: centroid fallback
      at(40.0, 3.0, 3.0),  // 3: far outside the box
      {nan, 0.0, 0.0},     // 4: corrupted position
  };
  std::vector<double> pos;
  for (const auto& p : pts) pos.insert(pos.end(), p.begin(), p.end());
  const std::size_t n = pts.size();
  for (const TransferKernel& k : {TransferKernel(GaussianKernel(1.0, 1)), TransferKernel(GaussianKernel(1.0, 2)),
                                  TransferKernel(CentroidKernel(1))}) {
    std::vector<double> field(g.localSize, 2.0), got(n);
    const TransferStats st = gatherToParcels(k, g.grid, g, n, pos.data(), 1, field.data(), got.data());
    EXPECT_EQ(st.orphans, 3u) << describe(k);
    EXPECT_EQ(st.orphanParcels, (std::vector<std::size_t>{1, 3, 4})) << describe(k);
    EXPECT_TRUE(std::isnan(got[1]) && std::isnan(got[3]) && std::isnan(got[4]));
    EXPECT_NEAR(got[0], 2.0, 1e-14);
    EXPECT_NEAR(got[2], 2.0, 1e-14);
    EXPECT_EQ(st.fallbacks, std::holds_alternative<CentroidKernel>(k) ? 1u : 0u) << describe(k);
    std::vector<double> one(n, 1.0), dep(g.localSize, 0.0);
    depositParcels(k, g.grid, g, n, pos.data(), 1, one.data(), dep.data());
    double total = 0.0;
    for (double v : dep) total += v;
    EXPECT_NEAR(total, 2.0, 1e-14) << "orphans deposit nothing, the others all of their volume";
  }
  // the centroid fallback goes to the nearest active cell
  Stencil s;
  ASSERT_EQ(stencilOf(CentroidKernel(1), g.grid, pts[2].data(), g, s), StencilResult::fallback);
  const auto ijk = g.ijkOf[s.cell[0]];
  double best = 1e300;
  for (int i = 5; i <= 7; ++i)
    for (int j = 4; j <= 6; ++j)
      if (g.active(i, j, 4)) {
        const double dx = g.grid.cellCentre(0, i) - pts[2][0], dy = g.grid.cellCentre(1, j) - pts[2][1];
        best = std::min(best, dx * dx + dy * dy);
      }
  const double dx = g.grid.cellCentre(0, ijk[0]) - pts[2][0], dy = g.grid.cellCentre(1, ijk[1]) - pts[2][1];
  EXPECT_EQ(ijk[2], 4);
  EXPECT_DOUBLE_EQ(dx * dx + dy * dy, best);
}

TEST(TransferKernelRegistry, SelectByNameAndRejectUnknownOrInvalid) {
  EXPECT_EQ(transferKernelNames(), (std::vector<std::string>{"gaussian", "centroid"}));
  EXPECT_TRUE(std::holds_alternative<GaussianKernel>(makeTransferKernel("gaussian")));
  EXPECT_TRUE(std::holds_alternative<CentroidKernel>(makeTransferKernel("centroid")));
  EXPECT_EQ(transferKernelName(makeTransferKernel("centroid")), "centroid");
  TransferKernelOptions o;
  o.gaussianRadius = 3;
  o.gaussianSharpness = 0.5;
  const auto k = std::get<GaussianKernel>(makeTransferKernel("gaussian", o));
  EXPECT_EQ(k.radius(), 3);
  EXPECT_EQ(k.sharpness(), 0.5);
  try {
    makeTransferKernel("Gaussian");  // names are case-sensitive
    FAIL();
  } catch (const parcelflow::cfd::ConfigError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("Gaussian"), std::string::npos) << m;
    EXPECT_NE(m.find("gaussian"), std::string::npos) << m;
    EXPECT_NE(m.find("centroid"), std::string::npos) << m;
  }
  EXPECT_NO_THROW(GaussianKernel(1.0, 4));
  EXPECT_THROW(GaussianKernel(1.0, 5), parcelflow::cfd::InternalError);
  EXPECT_THROW(GaussianKernel(0.0, 2), parcelflow::cfd::InternalError);
  EXPECT_THROW(CentroidKernel(-1), parcelflow::cfd::InternalError);
}
