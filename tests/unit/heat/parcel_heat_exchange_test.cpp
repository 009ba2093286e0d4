// The coupling step's heat exchange (coupling/run/parcel_heat_exchange.hpp) on 1, 2 and 3 ranks: what the
// parcels deposit and what they get back balance to round-off for any new gas temperature field, and one
// parcel in a uniform gas gets the coupled implicit step's H_eff with Gunn's H.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <random>

#include "coupling/run/parcel_heat_exchange.hpp"

namespace pc = parcelflow::coupling;

namespace {

constexpr double kPi = 3.14159265358979323846;

// 8 x 4 x 8 fluid cells of 1 cm, owned in turn by the ranks (every stencil crosses ranks).
struct Box {
  pc::BackgroundGrid grid;
  int rank = 0, nranks = 1;
  std::vector<long> owned;
  Box() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &nranks);
    grid.origin = {0.0, 0.0, 0.0};
    grid.spacing = {0.01, 0.01, 0.01};
    grid.cells = {8, 4, 8};
    for (long c = 0; c < 8 * 4 * 8; ++c)
      if (c % nranks == rank) owned.push_back(c);
  }
};

struct Parcels {
  std::vector<double> x, v, dp, np, mass, temperature, heat_capacity;
  std::vector<int> type;
  void add(std::array<double, 3> at, std::array<double, 3> vel, double d, double n, double T) {
    x.insert(x.end(), at.begin(), at.end());
    v.insert(v.end(), vel.begin(), vel.end());
    dp.push_back(d);
    np.push_back(n);
    mass.push_back(2500.0 * n * kPi / 6.0 * d * d * d);
    temperature.push_back(T);
    heat_capacity.push_back(mass.back() * 840.0);
    type.push_back(1);
  }
  pc::ParcelBatch batch() const {
    return {dp.size(), x.data(), v.data(), dp.data(), np.data(), mass.data(), type.data()};
  }
};

double sumAll(double v) {
  double r = 0.0;
  MPI_Allreduce(&v, &r, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  return r;
}

pc::ParcelHeatExchange gunnExchange() {
  return pc::ParcelHeatExchange(pc::makeNusseltCorrelation("Gunn"), pc::HeatLimits{0.3},
                                pc::GasThermalProperties{1.2, 1.8e-5, 0.026, 1005.0});
}

}  // namespace

TEST(ParcelHeatExchange, WhatTheGasGivesTheParcelsGet) {
  const Box box;
  pc::CellOwnerMap owners(MPI_COMM_WORLD, 8 * 4 * 8, box.owned);
  pc::ParcelMeshCoupler coupler(box.grid, owners, pc::makeTransferKernel("gaussian"), pc::makeDragLaw("WenYu"),
                                pc::DragLimits{0.3}, pc::GasProperties{1.2, 1.8e-5});
  Parcels parcels;  // different parcels on each rank, fines among them (dt H/(M c) far above 1)
  std::mt19937 rng(17 + box.rank);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int p = 0; p < 60; ++p)
    parcels.add({0.08 * u(rng), 0.04 * u(rng), 0.08 * u(rng)}, {0.1 * u(rng), 0.0, 0.3 * u(rng)},
                p % 3 == 0 ? 5e-5 : 5e-4, p % 2 ? 8.0 : 1.0, 300.0 + 100.0 * u(rng));
  coupler.beginStep(parcels.batch());
  std::vector<double> solid_fraction;
  coupler.depositSolids(solid_fraction);
  const int cells = coupler.ownedCells();
  std::vector<double> gas_fraction(cells), velocity(3 * cells, 0.0);
  for (int c = 0; c < cells; ++c) {
    gas_fraction[c] = std::max(1.0 - solid_fraction[c], 0.3);
    velocity[3 * c + 2] = 0.5;
  }
  pc::SolidsOnCells solids;
  pc::GasAtParcels at_parcels;
  coupler.computeDrag(gas_fraction, velocity, solids, at_parcels);
  coupler.gatherGas(velocity, std::vector<double>(3 * cells, 0.0), at_parcels);
  pc::ParcelHeatExchange exchange = gunnExchange();
  std::vector<double> coeff, source;
  const double dt = 1e-3;
  exchange.depositExchange(coupler, at_parcels, parcels.temperature.data(), parcels.heat_capacity.data(), dt, coeff,
                           source);
  // any new gas temperature: what the gas gains, sum (source - coeff T), against what the parcels get
  std::vector<double> T(cells);
  for (int c = 0; c < cells; ++c) T[c] = 350.0 + 30.0 * std::sin(static_cast<double>(box.owned[c]));
  std::vector<double> gas_at_parcels, held;
  const long orphans = exchange.gatherTemperature(coupler, T, gas_at_parcels, held);
  double gas_gain = 0.0, parcel_gain = 0.0, scale = 0.0;
  for (int c = 0; c < cells; ++c) {
    gas_gain += source[c] - coeff[c] * T[c];
    scale += std::fabs(coeff[c] * T[c]);
  }
  double beyond = 0.0;
  for (std::size_t p = 0; p < held.size(); ++p) {
    parcel_gain += held[p];
    // never beyond the gas temperature: T_p + dt S/(M c) lies between T_p and T_g
    const double after = parcels.temperature[p] + dt * held[p] / parcels.heat_capacity[p];
    const double lo = std::min(parcels.temperature[p], gas_at_parcels[p]), hi = std::max(parcels.temperature[p], gas_at_parcels[p]);
    beyond = std::max({beyond, lo - after, after - hi});
  }
  gas_gain = sumAll(gas_gain);
  parcel_gain = sumAll(parcel_gain);
  scale = sumAll(scale);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf("[ heat exchange ] gas gains %.12e W, parcels %.12e W: sum %.1e of %.3e W exchanged\n", gas_gain,
                parcel_gain, gas_gain + parcel_gain, scale);
  EXPECT_EQ(orphans, 0);
  EXPECT_LT(std::fabs(gas_gain + parcel_gain), 1e-13 * scale);
  EXPECT_LE(beyond, 1e-12);
}

TEST(ParcelHeatExchange, OneParcelInAUniformGasGetsTheCoupledImplicitStep) {
  const Box box;
  pc::CellOwnerMap owners(MPI_COMM_WORLD, 8 * 4 * 8, box.owned);
  pc::ParcelMeshCoupler coupler(box.grid, owners, pc::makeTransferKernel("gaussian"), pc::makeDragLaw("WenYu"),
                                pc::DragLimits{0.3}, pc::GasProperties{1.2, 1.8e-5});
  Parcels parcels;
  if (box.rank == 0) parcels.add({0.041, 0.022, 0.043}, {0.0, 0.0, 0.1}, 1e-4, 8.0, 300.0);
  coupler.beginStep(parcels.batch());
  const int cells = coupler.ownedCells();
  std::vector<double> gas_fraction(cells, 0.45), velocity(3 * cells, 0.0);
  for (int c = 0; c < cells; ++c) velocity[3 * c + 2] = 0.4;  // slip 0.3 m/s
  pc::SolidsOnCells solids;
  pc::GasAtParcels at_parcels;
  coupler.computeDrag(gas_fraction, velocity, solids, at_parcels);
  coupler.gatherGas(velocity, std::vector<double>(3 * cells, 0.0), at_parcels);
  pc::ParcelHeatExchange exchange = gunnExchange();
  std::vector<double> coeff, source, gas_at_parcels, held;
  const double dt = 0.05;
  exchange.depositExchange(coupler, at_parcels, parcels.temperature.data(), parcels.heat_capacity.data(), dt, coeff,
                           source);
  exchange.gatherTemperature(coupler, std::vector<double>(cells, 600.0), gas_at_parcels, held);
  double deposited = 0.0;
  for (int c = 0; c < cells; ++c) deposited += coeff[c];
  deposited = sumAll(deposited);
  if (box.rank == 0) {
    // Gunn at a_g 0.45, slip 0.3 m/s, d_p 100 um (python, as in test_parcel_heat): H = 3.954419e-04 W/K for np 8
    const double H = parcels.np[0] * pc::GunnNusselt().nusselt({0.45, 0.45 * 1.2 * 0.3 * 1e-4 / 1.8e-5,
                                                                1005.0 * 1.8e-5 / 0.026}) * 0.026 * kPi * 1e-4;
    const double mc = parcels.heat_capacity[0], heff = H * mc / (mc + dt * H);
    std::printf("[ heat exchange ] one parcel: H = %.6e W/K, M c = %.6e J/K, dt H/(M c) = %.2f, H_eff = %.6e W/K, "
                "deposited %.6e, S = %.6e W\n", H, mc, dt * H / mc, heff, deposited, held[0]);
    EXPECT_NEAR(H, 3.954419e-04, 1e-9);
    EXPECT_NEAR(deposited, heff, 1e-15);
    EXPECT_NEAR(held[0], heff * 300.0, 1e-12);
    EXPECT_NEAR(gas_at_parcels[0], 600.0, 1e-12);
  }
}
