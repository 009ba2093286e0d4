// Particle -> mesh transfer across ranks conserves parcel volume, drag coefficient and momentum to
// round-off, also next to walls and in an inside corner, on any number of ranks (issue 4, test 1).
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "coupling/run/parcel_mesh_coupler.h"
#include "tests/unit/coupling/transfer_conservation.hpp"

namespace pc = parcelflow::coupling;

namespace {

struct LShapedDomain {
  pc::BackgroundGrid grid;
  int rank = 0, nranks = 1;
  std::vector<long> owned;  // this rank's owned background cells
  long size() const { return static_cast<long>(grid.cells[0]) * grid.cells[1] * grid.cells[2]; }

  // 12 x 6 x 10 cells of 1 cm; fluid is an L: the block x > 6 cm, z > 5 cm is solid wall.
  LShapedDomain() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &nranks);
    grid.origin = {0.0, 0.0, 0.0};
    grid.spacing = {0.01, 0.01, 0.01};
    grid.cells = {12, 6, 10};
    long fluid = 0;
    for (long c = 0; c < size(); ++c) {
      if (!isFluid(c)) continue;
      if (fluid++ % nranks == rank) owned.push_back(c);  // scattered ownership: every stencil crosses ranks
    }
  }
  bool isFluid(long c) const {
    const long i = c % grid.cells[0], k = c / (grid.cells[0] * grid.cells[1]);
    return !(i >= 6 && k >= 5);
  }
};

// Parcels anywhere in the fluid part, many of them within a kernel width of a wall or the corner.
struct Parcels {
  std::vector<double> x, v, dp, np;
  explicit Parcels(const LShapedDomain& s, int count) {
    std::mt19937 rng(7 + s.rank);
    std::uniform_real_distribution<double> ux(0.0, 0.12), uy(0.0, 0.06), uz(0.0, 0.10), uv(-1.0, 1.0);
    while (static_cast<int>(dp.size()) < count) {
      const double p[3] = {ux(rng), uy(rng), uz(rng)};
      if (p[0] >= 0.06 && p[2] >= 0.05) continue;
      x.insert(x.end(), p, p + 3);
      v.insert(v.end(), {uv(rng), uv(rng), uv(rng)});
      dp.push_back(1e-4 * (1.0 + (rng() % 5)));
      np.push_back(1.0 + (rng() % 27));
    }
  }
  pc::ParcelBatch batch() const { return {dp.size(), x.data(), v.data(), dp.data(), np.data()}; }
};

}  // namespace

// The L-shaped domain with its coupler, for the kernel the test is run with.
class Conservation : public ::testing::TestWithParam<const char*> {
 protected:
  LShapedDomain s;
  pc::CellOwnerMap owners{MPI_COMM_WORLD, s.size(), s.owned};
  pc::ParcelMeshCoupler coupler{s.grid, owners, pc::makeTransferKernel(GetParam()), pc::makeDragLaw("WenYu"),
                                pc::DragLimits{0.3}, pc::GasProperties{1.2, 1.8e-5}};
};

TEST_P(Conservation, VolumeDragAndMomentumReachTheOwnersExactly) {
  const Parcels parcels(s, 400);
  const pc::TransferStats stats = coupler.beginStep(parcels.batch());
  EXPECT_EQ(pc::test::sumOverRanks(static_cast<double>(stats.orphans)), 0.0);

  const pc::test::ConservationErrors e = pc::test::transferConservation(coupler, parcels.batch(), s.owned.size());
  if (s.rank == 0)
    std::printf("[%s kernel, %d rank(s)] relative errors: volume %.2e, kappa %.2e, momentum %.2e; "
                "max gather error of a uniform field %.2e\n",
                GetParam(), s.nranks, e.volume, e.kappa, e.momentum, e.gather);
  EXPECT_LT(e.volume, 1e-12);
  EXPECT_LT(e.kappa, 1e-12);
  EXPECT_LT(e.momentum, 1e-12);
  EXPECT_LT(e.gather, 1e-14);
}

INSTANTIATE_TEST_SUITE_P(Kernels, Conservation, ::testing::Values("gaussian", "centroid"));

// The squared-weight deposit gives sum_p w_pc^2 q_p on every owned cell, with w_pc read off a deposit of each
// parcel alone (so at walls, in the corner and across ranks the weights are the coupler's own).
TEST_P(Conservation, SquaredWeightsDepositTheSquaresOfTheParcelsWeights) {
  const Parcels parcels(s, 30);
  coupler.beginStep(parcels.batch());
  const int n = static_cast<int>(parcels.dp.size());
  std::vector<double> expected(s.owned.size(), 0.0), alone(n, 0.0), weights;
  for (int r = 0; r < s.nranks; ++r) {
    int count = n;
    MPI_Bcast(&count, 1, MPI_INT, r, MPI_COMM_WORLD);
    for (int p = 0; p < count; ++p) {  // one parcel of one rank at a time; the deposit is collective
      std::fill(alone.begin(), alone.end(), 0.0);
      if (r == s.rank) alone[p] = std::sqrt(parcels.np[p]);
      coupler.depositToOwners(alone, 1, weights);  // w_pc sqrt(q_p)
      for (std::size_t c = 0; c < weights.size(); ++c) expected[c] += weights[c] * weights[c];
    }
  }
  std::vector<double> squared;
  coupler.depositSquaredWeightsToOwners(parcels.np, 1, squared);
  double largest = 0.0, error = 0.0;
  for (std::size_t c = 0; c < squared.size(); ++c) {
    largest = std::max(largest, expected[c]);
    error = std::max(error, std::abs(squared[c] - expected[c]));
  }
  EXPECT_GT(largest, 0.0);
  EXPECT_LT(error, 1e-13 * largest);
}

// BVK's polydisperse correction needs the local Sauter mean <d> = sum np dp^3 / sum np dp^2. Every
// position holds one parcel of each size, so both moments are the same field times a constant and <d>
// is 81e-12 / 45e-8 = 1.8e-4 m at every parcel, whatever the kernel, walls or ranks.
class SauterMean : public ::testing::TestWithParam<const char*> {};

TEST_P(SauterMean, BeetstraDragGetsTheLocalSauterMean) {
  LShapedDomain s;
  pc::CellOwnerMap owners(MPI_COMM_WORLD, s.size(), s.owned);
  const pc::GasProperties gas{1.2, 1.8e-5};
  pc::ParcelMeshCoupler coupler(s.grid, owners, pc::makeTransferKernel(GetParam()),
                                pc::makeDragLaw("BeetstraVanDerHoefKuipers"), pc::DragLimits{0.3}, gas);
  Parcels parcels(s, 200);
  const std::size_t positions = parcels.dp.size();
  // small: 27 of 0.1 mm; large: 2 of 0.3 mm at the same place and velocity
  const std::vector<double> x = parcels.x, v = parcels.v;
  parcels.x.insert(parcels.x.end(), x.begin(), x.end());
  parcels.v.insert(parcels.v.end(), v.begin(), v.end());
  parcels.dp.assign(positions, 1e-4);
  parcels.np.assign(positions, 27);
  parcels.dp.resize(2 * positions, 3e-4);
  parcels.np.resize(2 * positions, 2);
  coupler.beginStep(parcels.batch());
  std::vector<double> solid_fraction;
  coupler.depositSolids(solid_fraction);
  const std::vector<double> gas_fraction(s.owned.size(), 0.6);
  std::vector<double> velocity;
  for (std::size_t c = 0; c < s.owned.size(); ++c) velocity.insert(velocity.end(), {0.1, -0.2, 0.8});
  pc::SolidsOnCells solids;
  pc::GasAtParcels at_parcels;
  const pc::DragStats stats = coupler.computeDrag(gas_fraction, velocity, solids, at_parcels);
  EXPECT_EQ(stats.invalidInput, 0u);

  const double sauter = 1.8e-4;
  double max_mean_error = 0.0, max_kappa_error = 0.0, min_polydisperse_effect = 1.0;
  for (std::size_t p = 0; p < parcels.dp.size(); ++p) {
    pc::DragInput in;
    in.alphaG = 0.6;
    in.rhoG = gas.density;
    in.muG = gas.viscosity;
    in.dp = parcels.dp[p];
    in.slip = std::hypot(0.1 - parcels.v[3 * p], -0.2 - parcels.v[3 * p + 1], 0.8 - parcels.v[3 * p + 2]);
    const double monodisperse = pc::BeetstraDrag{}.coefficient(in);
    in.dMean = sauter;
    const double expected = pc::parcelKappa(parcels.np[p], in.dp, pc::BeetstraDrag{}.coefficient(in));
    max_mean_error = std::max(max_mean_error, std::abs(at_parcels.mean_diameter[p] / sauter - 1.0));
    max_kappa_error = std::max(max_kappa_error, std::abs(at_parcels.kappa[p] / expected - 1.0));
    min_polydisperse_effect = std::min(
        min_polydisperse_effect, std::abs(pc::parcelKappa(parcels.np[p], in.dp, monodisperse) / expected - 1.0));
  }
  if (s.rank == 0)
    std::printf("[%s kernel, %d rank(s)] Sauter mean max relative error %.2e, BVK kappa %.2e "
                "(the correction changes kappa by at least %.1f %%)\n",
                GetParam(), s.nranks, max_mean_error, max_kappa_error, 100 * min_polydisperse_effect);
  EXPECT_LT(max_mean_error, 1e-12);
  EXPECT_LT(max_kappa_error, 1e-12);
  EXPECT_GT(min_polydisperse_effect, 0.05);
}

INSTANTIATE_TEST_SUITE_P(Kernels, SauterMean, ::testing::Values("gaussian", "centroid"));
