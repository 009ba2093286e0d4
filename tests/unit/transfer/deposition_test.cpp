// Deposition and gather: conservation of particle volume and momentum (kappa v) for many random
// parcels on an L-shaped mask, the same results (to round-off) from the ghost-deposition oracle and the
// box stencils the coupler uses, and action = -reaction of the drag force between parcels and gas cells.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "coupling/transfer/box_stencils.hpp"
#include "tests/support/ghost_deposition_oracle.hpp"
#include "tests/unit/transfer/test_grid.hpp"

using namespace parcelflow::coupling;
using namespace parcelflow::coupling::test;

namespace {

struct Parcels {
  std::vector<double> pos, volume, kappa, v;
  std::size_t size() const { return volume.size(); }
};

Parcels randomParcels(const MaskedGrid& g, std::size_t n, unsigned seed) {
  Parcels p;
  p.pos = test::randomActivePositions(g, n, seed);
  std::mt19937_64 rng(seed + 1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double dp = 1e-4 * (1.0 + 9.0 * u(rng)), np = 1.0 + 1e4 * u(rng);
    p.volume.push_back(np * 3.14159265358979323846 / 6.0 * dp * dp * dp);
    p.kappa.push_back(1e-6 * (0.01 + u(rng)));
    for (int d = 0; d < 3; ++d) p.v.push_back(2.0 * u(rng) - 1.0);
  }
  return p;
}

std::vector<TransferKernel> kernels() {
  const double spacing[3] = {0.01, 0.02, 0.015};  // the test grid's (test_grid.hpp): h = cbrt(cell volume)
  return {GaussianKernel(1.0, 2), GaussianKernel(1.0, 1), GaussianKernel(0.5, 3), GaussianKernel(1.0, 2, spacing),
          CentroidKernel(1)};
}

const char* name(const TransferKernel& k) { return std::holds_alternative<GaussianKernel>(k) ? "gaussian" : "centroid"; }

FluidCells fluidOf(const MaskedGrid& g) {
  return FluidCells(g.grid, [&](int i, int j, int k) { return g.active(i, j, k); });
}

// Box values of the fluid cells at their local indices (what the coupler sends to the owners).
std::vector<double> boxToLocal(const MaskedGrid& g, const BoxStencils& s, int nc, const std::vector<double>& box) {
  std::vector<double> local(static_cast<std::size_t>(nc) * g.localSize, 0.0);
  for (int c = 0; c < g.localSize; ++c) {
    const auto& ijk = g.ijkOf[c];
    if (ijk[0] < 0) continue;
    bool inBox = true;
    for (int d = 0; d < 3; ++d) inBox = inBox && ijk[d] >= s.lo[d] && ijk[d] < s.lo[d] + s.cells[d];
    if (!inBox) continue;
    const long b = s.boxIndex(ijk[0], ijk[1], ijk[2]);
    for (int m = 0; m < nc; ++m) local[nc * c + m] = box[nc * b + m];
  }
  return local;
}

// Local cell values on the box, 0 on non-fluid box cells (what the coupler fetches from the owners).
std::vector<double> localToBox(const MaskedGrid& g, const BoxStencils& s, int nc, const std::vector<double>& local) {
  std::vector<double> box(static_cast<std::size_t>(nc) * s.boxSize(), 0.0);
  for (int k = s.lo[2]; k < s.lo[2] + s.cells[2]; ++k)
    for (int j = s.lo[1]; j < s.lo[1] + s.cells[1]; ++j)
      for (int i = s.lo[0]; i < s.lo[0] + s.cells[0]; ++i)
        if (g.active(i, j, k))
          for (int m = 0; m < nc; ++m) box[nc * s.boxIndex(i, j, k) + m] = local[nc * g(i, j, k) + m];
  return box;
}

// max |a - b| / max |b|
double relativeDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double diff = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    diff = std::max(diff, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(b[i]));
  }
  return diff / scale;
}

}  // namespace

TEST(Deposition, ConservesVolumeAndMomentumOfRandomParcels) {
  const MaskedGrid g = makeGrid({12, 10, 8}, true);
  const Parcels p = randomParcels(g, 20000, 5);
  const std::size_t n = p.size();
  // q = [volume, kappa, kappa vx, kappa vy, kappa vz] per parcel
  std::vector<double> q(5 * n);
  double totals[5] = {0, 0, 0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    q[5 * i] = p.volume[i];
    q[5 * i + 1] = p.kappa[i];
    for (int d = 0; d < 3; ++d) q[5 * i + 2 + d] = p.kappa[i] * p.v[3 * i + d];
    for (int m = 0; m < 5; ++m) totals[m] += q[5 * i + m];
  }
  for (const TransferKernel& k : kernels()) {
    std::vector<double> cells(5 * g.localSize, 0.0);
    const TransferStats st = depositParcels(k, g.grid, g, n, p.pos.data(), 5, q.data(), cells.data());
    ASSERT_EQ(st.orphans, 0u);
    double worst = 0.0;
    for (int m = 0; m < 5; ++m) {
      double sum = 0.0, scale = 0.0;
      for (int c = 0; c < g.localSize; ++c) sum += cells[5 * c + m];
      for (std::size_t i = 0; i < n; ++i) scale += std::abs(q[5 * i + m]);
      const double rel = std::abs(sum - totals[m]) / scale;
      worst = std::max(worst, rel);
      EXPECT_LE(rel, 1e-12) << name(k) << " component " << m;
    }
    for (int c = 0; c < g.localSize; ++c)
      if (g.ijkOf[c][0] < 0) {
        ASSERT_EQ(cells[5 * c], 0.0) << "deposit into a gap index";
      }
    std::printf("[measured] %s: volume/kappa/kappa v conserved to %.2e relative (%zu parcels)\n", name(k),
                worst, n);

    // The box stencils give the same cell values; only the rounding differs (the renormalisation sum
    // of an all-fluid window is the product of its per-axis sums).
    BoxStencils set;
    const TransferStats st2 = buildBoxStencils(k, g.grid, fluidOf(g), n, p.pos.data(), set);
    EXPECT_EQ(st2.orphans, 0u);
    EXPECT_EQ(st2.fallbacks, st.fallbacks);
    std::vector<double> box(5 * set.boxSize(), 0.0);
    deposit(set, 5, q.data(), box.data());
    const double diff = relativeDifference(boxToLocal(g, set, 5, box), cells);
    std::printf("[measured] %s: box stencils' cell values differ by %.2e relative\n", name(k), diff);
    EXPECT_LE(diff, 1e-14);
  }
}

TEST(Deposition, DragActionEqualsMinusReaction) {
  // Parcel force F_p = kappa_p (u(x_p) - v_p) with u gathered by the kernel; gas force in cell c
  // = sum_p w_pc kappa_p v_p - u_c sum_p w_pc kappa_p (what the gas solver builds from the deposited
  // kappa v and kappa: explicit source and implicit diagonal). sum_c gas + sum_p parcel = 0.
  const MaskedGrid g = makeGrid({12, 10, 8}, true);
  const Parcels p = randomParcels(g, 20000, 9);
  const std::size_t n = p.size();
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> uCell(3 * g.localSize);
  for (double& x : uCell) x = 3.0 * u(rng);
  for (const TransferKernel& k : kernels()) {
    BoxStencils set;
    buildBoxStencils(k, g.grid, fluidOf(g), n, p.pos.data(), set);
    std::vector<double> uP(3 * n);
    gather(set, 3, localToBox(g, set, 3, uCell).data(), uP.data());
    double parcelSum[3] = {0, 0, 0}, scale = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d) {
        const double f = p.kappa[i] * (uP[3 * i + d] - p.v[3 * i + d]);
        parcelSum[d] += f;
        scale += std::abs(f);
      }
    // What the coupler deposits: [kappa, kappa v] per parcel.
    std::vector<double> q(4 * n), box(4 * set.boxSize(), 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      q[4 * i] = p.kappa[i];
      for (int d = 0; d < 3; ++d) q[4 * i + 1 + d] = p.kappa[i] * p.v[3 * i + d];
    }
    deposit(set, 4, q.data(), box.data());
    const std::vector<double> cells = boxToLocal(g, set, 4, box);
    double worst = 0.0;
    for (int d = 0; d < 3; ++d) {
      double gasSum = 0.0;
      for (int c = 0; c < g.localSize; ++c) gasSum += cells[4 * c + 1 + d] - cells[4 * c] * uCell[3 * c + d];
      const double rel = std::abs(gasSum + parcelSum[d]) / scale;
      worst = std::max(worst, rel);
      EXPECT_LE(rel, 1e-12) << name(k) << " axis " << d;
    }
    std::printf("[measured] %s: |sum F_gas + sum F_parcels| / sum |F_parcel| = %.2e\n", name(k), worst);

    // the oracle's gather gives the same parcel velocities as the box stencils, to round-off
    std::vector<double> uP2(3 * n);
    gatherToParcels(k, g.grid, g, n, p.pos.data(), 3, uCell.data(), uP2.data());
    EXPECT_LE(relativeDifference(uP, uP2), 1e-14);
  }
}

TEST(Deposition, ParcelsWiderThanTheCellConserveVolumeAndActionEqualsReaction) {
  // Coarse-grained parcels of 5-60 mm on the L-shaped mask of 10-20 mm cells (h = 14.4 mm), with the
  // kernel widened to lambda D: their windows reach up to +-4 cells, over walls and the inside corner.
  const MaskedGrid g = makeGrid({12, 10, 8}, true);
  const Parcels p = randomParcels(g, 20000, 21);
  const std::size_t n = p.size();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> diameter(n), uCell(3 * g.localSize);
  for (double& d : diameter) d = 0.005 + 0.055 * u(rng);
  for (double& x : uCell) x = 2.0 * u(rng) - 1.0;
  const double spacing[3] = {0.01, 0.02, 0.015};
  for (const bool isotropic : {true, false}) {
    BoxStencils set;
    const TransferStats st = buildBoxStencils(GaussianKernel(1.0, 2, spacing, isotropic, 1.0), g.grid, fluidOf(g), n,
                                              p.pos.data(), set, diameter.data());
    ASSERT_EQ(st.orphans, 0u);
    std::vector<double> q(4 * n), box(4 * set.boxSize(), 0.0), uP(3 * n);
    double volume = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      q[4 * i] = p.volume[i];
      volume += p.volume[i];
      for (int d = 0; d < 3; ++d) q[4 * i + 1 + d] = p.kappa[i] * p.v[3 * i + d];
    }
    deposit(set, 4, q.data(), box.data());
    const std::vector<double> cells = boxToLocal(g, set, 4, box);
    double deposited = 0.0;
    for (int c = 0; c < g.localSize; ++c) deposited += cells[4 * c];
    EXPECT_LE(std::abs(deposited - volume) / volume, 1e-12);
    // action = -reaction with the same weights both ways: sum_c (kappa v)_c - u_c kappa_c = -sum_p F_p
    for (std::size_t i = 0; i < n; ++i) q[4 * i] = p.kappa[i];
    std::fill(box.begin(), box.end(), 0.0);
    deposit(set, 4, q.data(), box.data());
    const std::vector<double> drag = boxToLocal(g, set, 4, box);
    gather(set, 3, localToBox(g, set, 3, uCell).data(), uP.data());
    for (int d = 0; d < 3; ++d) {
      double gasSum = 0.0, parcelSum = 0.0, scale = 0.0;
      for (int c = 0; c < g.localSize; ++c) gasSum += drag[4 * c + 1 + d] - drag[4 * c] * uCell[3 * c + d];
      for (std::size_t i = 0; i < n; ++i) {
        const double f = p.kappa[i] * (uP[3 * i + d] - p.v[3 * i + d]);
        parcelSum += f;
        scale += std::abs(f);
      }
      EXPECT_LE(std::abs(gasSum + parcelSum) / scale, 1e-12) << (isotropic ? "cell_volume" : "cell_axes") << d;
    }
  }
}

namespace {

// Parcel centres of volume 1 spread evenly along x over the fluid cells 0..fluidCells-1 of g's row (perCell per
// cell, on the middle y and z), deposited with the cell_volume Gaussian: the volume each x column of fluid cells
// receives.
std::vector<double> volumePerColumn(const MaskedGrid& g, int fluidCells, int perCell, bool reflect) {
  const int n = fluidCells * perCell;
  std::vector<double> pos;
  for (int p = 0; p < n; ++p) {
    pos.push_back(g.grid.origin[0] + (p + 0.5) / perCell * g.grid.spacing[0]);
    pos.push_back(g.grid.cellCentre(1, 1));
    pos.push_back(g.grid.cellCentre(2, 1));
  }
  const std::vector<double> volume(n, 1.0);
  const double spacing[3] = {0.01, 0.02, 0.015};
  BoxStencils set;
  buildBoxStencils(GaussianKernel(1.0, 2, spacing, true, 0.0, reflect), g.grid, fluidOf(g), n, pos.data(), set);
  std::vector<double> box(set.boxSize(), 0.0);
  deposit(set, 1, volume.data(), box.data());
  std::vector<double> column(g.grid.cells[0], 0.0);
  for (int k = set.lo[2]; k < set.lo[2] + set.cells[2]; ++k)
    for (int j = set.lo[1]; j < set.lo[1] + set.cells[1]; ++j)
      for (int i = set.lo[0]; i < set.lo[0] + set.cells[0]; ++i)
        if (g.active(i, j, k)) column[i] += box[set.boxIndex(i, j, k)];
  return column;
}

// The largest |column / perCell - 1| over the first `fluidCells` columns.
double largestDeviation(const std::vector<double>& column, int fluidCells, int perCell) {
  double worst = 0.0;
  for (int i = 0; i < fluidCells; ++i) worst = std::max(worst, std::abs(column[i] / perCell - 1.0));
  return worst;
}

}  // namespace

TEST(Deposition, ReflectingFacesDepositUniformCentresUniformly) {
  // Parcel centres spread evenly over the whole box along x (100 per cell): with reflecting faces every
  // cell receives the same volume (the images fill in what the faces cut off: int_0^L K(y-x) + K(y+x) dx
  // is 1 for every y far from the other face), while truncating and renormalising piles volume into the
  // cells next to the faces. Measured and asserted both ways, so that the test tells them apart.
  const MaskedGrid g = makeGrid({40, 3, 3}, false);
  const double reflect = largestDeviation(volumePerColumn(g, 40, 100, true), 40, 100);
  const double truncate = largestDeviation(volumePerColumn(g, 40, 100, false), 40, 100);
  std::printf("[measured] largest deviation of a cell from the mean: reflect %.2e, truncate %.2e\n", reflect,
              truncate);
  EXPECT_LE(reflect, 1e-3);
  EXPECT_GE(truncate, 1e-2);
}

TEST(Deposition, ReflectingWallsInsideTheBoxDepositUniformCentresUniformly) {
  // The same inside the box: the cells i >= 30 of a 40-cell row are solid (a staircase wall), and parcel centres
  // spread evenly over the fluid cells 0..29 deposit evenly up to that wall when it reflects; truncating piles
  // volume next to it as at a face.
  MaskedGrid g = makeGrid({40, 3, 3}, false);
  const int fluidCells = 30, perCell = 100;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = fluidCells; i < 40; ++i) g.local[(static_cast<std::size_t>(k) * 3 + j) * 40 + i] = -1;
  double deviation[2];
  for (const bool reflect : {true, false}) {
    const std::vector<double> column = volumePerColumn(g, fluidCells, perCell, reflect);
    double total = 0.0;
    for (double v : column) total += v;
    EXPECT_NEAR(total, fluidCells * perCell, 1e-9 * fluidCells * perCell);  // nothing lands on the solid cells
    deviation[reflect ? 0 : 1] = largestDeviation(column, fluidCells, perCell);
  }
  std::printf("[measured] inside wall, largest deviation of a cell from the mean: reflect %.2e, truncate %.2e\n",
              deviation[0], deviation[1]);
  EXPECT_LE(deviation[0], 1e-3);
  EXPECT_GE(deviation[1], 1e-2);
}

TEST(BoxStencils, OrphansAreMarkedAndGatherNaN) {
  const MaskedGrid g = makeGrid({12, 10, 8}, true);
  const auto& G = g.grid;
  // The second parcel sits in the cut-out block, more than R = 1 cells from any fluid cell.
  const std::vector<double> pos = {G.origin[0] + 3.5 * G.spacing[0], G.origin[1] + 3.5 * G.spacing[1], G.origin[2] + 0.05,
                                   G.origin[0] + 9.5 * G.spacing[0], G.origin[1] + 8.5 * G.spacing[1], G.origin[2] + 0.05,
                                   G.origin[0] + 2.5 * G.spacing[0], G.origin[1] + 1.5 * G.spacing[1], G.origin[2] + 0.05};
  BoxStencils set;
  const TransferStats st = buildBoxStencils(GaussianKernel(1.0, 1), G, fluidOf(g), 3, pos.data(), set);
  EXPECT_EQ(st.orphanParcels, (std::vector<std::size_t>{1}));
  ASSERT_EQ(set.parcels(), 3u);
  EXPECT_GE(set.first[0], 0);
  EXPECT_EQ(set.first[1], -1);
  EXPECT_GE(set.first[2], 0);
  // The box spans the two windows only: cells 1..4 in x, 0..4 in y.
  EXPECT_EQ(set.lo[0], 1);
  EXPECT_EQ(set.cells[0], 4);
  EXPECT_EQ(set.cells[1], 5);
  const std::vector<double> localField(g.localSize, 1.5);
  const std::vector<double> field = localToBox(g, set, 1, localField);
  std::vector<double> out(3);
  gather(set, 1, field.data(), out.data());
  EXPECT_NEAR(out[0], 1.5, 1e-14);
  EXPECT_TRUE(std::isnan(out[1]));
  EXPECT_NEAR(out[2], 1.5, 1e-14);
  gather(set, 1, field.data(), out.data(), 0.0);  // caller-chosen value for orphans
  EXPECT_EQ(out[1], 0.0);
  std::vector<double> out2(3);
  gatherToParcels(GaussianKernel(1.0, 1), G, g, 3, pos.data(), 1, localField.data(), out2.data(), -7.0);
  EXPECT_EQ(out2[1], -7.0);
  EXPECT_NEAR(out2[0], 1.5, 1e-14);
}
