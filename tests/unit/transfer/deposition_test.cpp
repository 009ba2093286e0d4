// Deposition and gather: conservation of particle volume and momentum (kappa v) for many random
// parcels on an L-shaped mask, identical results of the on-the-fly and cached-stencil paths, and
// action = -reaction of the drag force between parcels and gas cells.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "stencil_set.hpp"
#include "test_grid.hpp"

using namespace parcelflow::coupling;
using parcelflow::coupling::test::makeGrid;
using parcelflow::coupling::test::MaskedGrid;

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
  return {GaussianKernel(1.0, 2), GaussianKernel(1.0, 1), GaussianKernel(0.5, 3), CentroidKernel(1)};
}

const char* name(const TransferKernel& k) { return std::holds_alternative<GaussianKernel>(k) ? "gaussian" : "centroid"; }

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

    // cached stencils give the same cell values
    StencilSet set;
    const TransferStats st2 = buildStencils(k, g.grid, g, n, p.pos.data(), set);
    EXPECT_EQ(st2.orphans, 0u);
    std::vector<double> cached(5 * g.localSize, 0.0);
    deposit(set, 5, q.data(), cached.data());
    EXPECT_EQ(cached, cells);
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
    StencilSet set;
    buildStencils(k, g.grid, g, n, p.pos.data(), set);
    std::vector<double> uP(3 * n);
    gather(set, 3, uCell.data(), uP.data());
    double parcelSum[3] = {0, 0, 0}, scale = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d) {
        const double f = p.kappa[i] * (uP[3 * i + d] - p.v[3 * i + d]);
        parcelSum[d] += f;
        scale += std::abs(f);
      }
    // What the coupler deposits: [kappa, kappa v] per parcel.
    std::vector<double> q(4 * n), cells(4 * g.localSize, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      q[4 * i] = p.kappa[i];
      for (int d = 0; d < 3; ++d) q[4 * i + 1 + d] = p.kappa[i] * p.v[3 * i + d];
    }
    deposit(set, 4, q.data(), cells.data());
    double worst = 0.0;
    for (int d = 0; d < 3; ++d) {
      double gasSum = 0.0;
      for (int c = 0; c < g.localSize; ++c) gasSum += cells[4 * c + 1 + d] - cells[4 * c] * uCell[3 * c + d];
      const double rel = std::abs(gasSum + parcelSum[d]) / scale;
      worst = std::max(worst, rel);
      EXPECT_LE(rel, 1e-12) << name(k) << " axis " << d;
    }
    std::printf("[measured] %s: |sum F_gas + sum F_parcels| / sum |F_parcel| = %.2e\n", name(k), worst);

    // the on-the-fly gather gives the same parcel velocities as the cached stencils
    std::vector<double> uP2(3 * n);
    gatherToParcels(k, g.grid, g, n, p.pos.data(), 3, uCell.data(), uP2.data());
    EXPECT_EQ(uP, uP2);
  }
}

TEST(StencilSet, OrphanRowsAreEmptyAndGatherNaN) {
  const MaskedGrid g = makeGrid({12, 10, 8}, true);
  const auto& G = g.grid;
  const std::vector<double> pos = {G.origin[0] + 3.5 * G.spacing[0], G.origin[1] + 3.5 * G.spacing[1], G.origin[2] + 0.05,
                                   G.origin[0] + 9.5 * G.spacing[0], G.origin[1] + 8.5 * G.spacing[1], G.origin[2] + 0.05,
                                   G.origin[0] + 2.5 * G.spacing[0], G.origin[1] + 1.5 * G.spacing[1], G.origin[2] + 0.05};
  StencilSet set;
  const TransferStats st = buildStencils(GaussianKernel(1.0, 1), G, g, 3, pos.data(), set);
  EXPECT_EQ(st.orphanParcels, (std::vector<std::size_t>{1}));
  ASSERT_EQ(set.parcels(), 3u);
  EXPECT_EQ(set.offset[1] - set.offset[0], 27u);
  EXPECT_EQ(set.offset[2], set.offset[1]);
  EXPECT_EQ(set.offset[3] - set.offset[2], 27u);
  std::vector<double> field(g.localSize, 1.5), out(3);
  gather(set, 1, field.data(), out.data());
  EXPECT_NEAR(out[0], 1.5, 1e-14);
  EXPECT_TRUE(std::isnan(out[1]));
  EXPECT_NEAR(out[2], 1.5, 1e-14);
  gather(set, 1, field.data(), out.data(), 0.0);  // caller-chosen value for orphans
  EXPECT_EQ(out[1], 0.0);
  std::vector<double> out2(3);
  gatherToParcels(GaussianKernel(1.0, 1), G, g, 3, pos.data(), 1, field.data(), out2.data(), -7.0);
  EXPECT_EQ(out2[1], -7.0);
  EXPECT_NEAR(out2[0], 1.5, 1e-14);
}
