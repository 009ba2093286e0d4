// coupling.class_collisions on the coupler (run/class_collision_exchange.h): every parcel's type is a class of
// its cell, the force conserves momentum across ranks to round-off, and in one cell it is the model's
// acceleration of the class (with the parcels' velocity spread, unbiased, as its granular temperature) times
// the parcel's mass (issue 29).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <random>

#include "coupling/run/class_collision_exchange.h"
#include "tests/unit/coupling/transfer_conservation.hpp"

namespace pc = parcelflow::coupling;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDensity = 2526.0;

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

// Beads of 1.5 mm (type 1, rising at 0.2 m/s) and 2.5 mm (type 2, falling at 0.1 m/s) as parcels of np each,
// with velocity noise, at positions in [lo, hi).
struct Mixture {
  std::vector<double> x, v, dp, np, mass;
  std::vector<int> type;
  Mixture(int count, double parcels_np, std::array<double, 3> lo, std::array<double, 3> hi, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int p = 0; p < count; ++p) {
      const int t = 1 + p % 2;
      for (int d = 0; d < 3; ++d) x.push_back(lo[d] + (hi[d] - lo[d]) * u(rng));
      v.insert(v.end(), {0.05 * (u(rng) - 0.5), 0.05 * (u(rng) - 0.5), (t == 1 ? 0.2 : -0.1) + 0.05 * (u(rng) - 0.5)});
      dp.push_back(t == 1 ? 1.5e-3 : 2.5e-3);
      np.push_back(parcels_np);
      mass.push_back(kDensity * parcels_np * kPi / 6.0 * std::pow(dp.back(), 3));
      type.push_back(t);
    }
  }
  pc::ParcelBatch batch() const {
    return {dp.size(), x.data(), v.data(), dp.data(), np.data(), mass.data(), type.data()};
  }
};

struct Forces {
  std::vector<double> force;  // per parcel, interleaved xyz
  long uncorrected = 0;
};

// One coupling step's class-collision forces on the parcels, with a uniform gas fraction.
Forces classCollisionForces(const Box& box, const Mixture& parcels, const char* kernel,
                            pc::ClassCollisionParameters parameters, double gas_fraction, double dt, int types = 2) {
  pc::CellOwnerMap owners(MPI_COMM_WORLD, 8 * 4 * 8, box.owned);
  pc::ParcelMeshCoupler coupler(box.grid, owners, pc::makeTransferKernel(kernel), pc::makeDragLaw("WenYu"),
                                pc::DragLimits{0.3}, pc::GasProperties{1.2, 1.8e-5});
  coupler.beginStep(parcels.batch());
  pc::ClassCollisionExchange exchange(MPI_COMM_WORLD, types, parameters);
  Forces out;
  exchange.computeForces(coupler, std::vector<double>(box.owned.size(), gas_fraction), dt, out.force);
  out.uncorrected = exchange.uncorrected();
  return out;
}

}  // namespace

TEST(ClassCollisionExchange, ConservesMomentumAcrossRanksAndSlowsTheSlip) {
  Box box;
  const Mixture parcels(3000, 8.0, {0.0, 0.0, 0.0}, {0.08, 0.04, 0.08}, 11 + box.rank);
  const Forces result = classCollisionForces(box, parcels, "gaussian", {0.97, 0.1}, 0.45, 1e-4);
  const std::vector<double>& force = result.force;
  ASSERT_EQ(force.size(), 3 * parcels.dp.size());
  double total[3] = {0, 0, 0}, magnitude = 0.0, on_type[2] = {0, 0};
  for (std::size_t p = 0; p < parcels.dp.size(); ++p) {
    for (int d = 0; d < 3; ++d) total[d] += force[3 * p + d];
    magnitude += std::abs(force[3 * p + 2]);
    on_type[parcels.type[p] - 1] += force[3 * p + 2];
  }
  magnitude = pc::test::sumOverRanks(magnitude);
  EXPECT_GT(magnitude, 0.0);
  for (double f : total) EXPECT_LT(std::abs(pc::test::sumOverRanks(f)), 1e-12 * magnitude);
  EXPECT_LT(pc::test::sumOverRanks(on_type[0]), -0.4 * magnitude);  // the rising small beads are held back
  EXPECT_GT(pc::test::sumOverRanks(on_type[1]), 0.4 * magnitude);
  EXPECT_EQ(result.uncorrected, 0);
}

TEST(ClassCollisionExchange, InOneCellEachParcelGetsItsMassTimesItsClassAcceleration) {
  Box box;
  // every parcel of every rank in cell (3, 1, 4)
  const Mixture parcels(40, 8.0, {0.03, 0.01, 0.04}, {0.04, 0.02, 0.05}, 5 + box.rank);
  const double gas_fraction = 0.5, dt = 2e-4;
  const std::vector<double> force = classCollisionForces(box, parcels, "centroid", {0.9, 0.2}, gas_fraction, dt).force;

  // the cell's two classes, summed over all ranks' parcels here
  double sums[2][7] = {};  // mass, mass vz, mass vx, mass vy, volume, mass |v|^2, mass^2
  for (std::size_t p = 0; p < parcels.dp.size(); ++p) {
    double* s = sums[parcels.type[p] - 1];
    s[0] += parcels.mass[p];
    s[1] += parcels.mass[p] * parcels.v[3 * p + 2];
    s[2] += parcels.mass[p] * parcels.v[3 * p];
    s[3] += parcels.mass[p] * parcels.v[3 * p + 1];
    s[4] += parcels.mass[p] / kDensity;
    for (int d = 0; d < 3; ++d) s[5] += parcels.mass[p] * parcels.v[3 * p + d] * parcels.v[3 * p + d];
    s[6] += parcels.mass[p] * parcels.mass[p];
  }
  pc::CollisionClass classes[2];
  for (int t = 0; t < 2; ++t) {
    for (double& s : sums[t]) s = pc::test::sumOverRanks(s);
    classes[t].solid_fraction = sums[t][4] / 1e-6;
    classes[t].density = kDensity;
    classes[t].diameter = t == 0 ? 1.5e-3 : 2.5e-3;
    classes[t].parcel_diameter = 2.0 * classes[t].diameter;  // np 8
    classes[t].velocity[0] = sums[t][2] / sums[t][0];
    classes[t].velocity[1] = sums[t][3] / sums[t][0];
    classes[t].velocity[2] = sums[t][1] / sums[t][0];
    double mean_square = 0.0;
    for (double u : classes[t].velocity) mean_square += u * u;
    // the mass-weighted sample variance about the class's own mean (unbiased: n / (n - 1) for n parcels)
    classes[t].temperature = (sums[t][5] / sums[t][0] - mean_square) / 3.0 * sums[t][0] * sums[t][0] /
                             (sums[t][0] * sums[t][0] - sums[t][6]);
    EXPECT_NEAR(classes[t].temperature, 0.05 * 0.05 / 12.0, 0.3 * 0.05 * 0.05 / 12.0);  // uniform noise of 0.05
  }
  double accel[6];
  pc::ClassCollisionDrag({0.9, 0.2}).accelerations(classes, 2, gas_fraction, dt, accel);
  EXPECT_LT(accel[2], 0.0);
  for (std::size_t p = 0; p < parcels.dp.size(); ++p)
    for (int d = 0; d < 3; ++d) {
      const double expected = parcels.mass[p] * accel[3 * (parcels.type[p] - 1) + d];
      EXPECT_NEAR(force[3 * p + d], expected, 1e-10 * std::abs(parcels.mass[p] * accel[2]));
    }
}

// Atom types no parcel has (a script's walls' type) are no classes: the large beads as type 3 of 5, with types 2,
// 4 and 5 empty, get the forces they get as type 2 of 2.
TEST(ClassCollisionExchange, TypesWithoutParcelsChangeNothing) {
  Box box;
  const Mixture parcels(600, 8.0, {0.0, 0.0, 0.0}, {0.08, 0.04, 0.08}, 17 + box.rank);
  Mixture renumbered = parcels;
  for (int& type : renumbered.type) type = type == 2 ? 3 : type;
  const Forces two = classCollisionForces(box, parcels, "gaussian", {0.97, 0.1}, 0.45, 1e-4);
  const Forces five = classCollisionForces(box, renumbered, "gaussian", {0.97, 0.1}, 0.45, 1e-4, 5);
  ASSERT_EQ(two.force.size(), five.force.size());
  for (std::size_t i = 0; i < two.force.size(); ++i) EXPECT_EQ(two.force[i], five.force[i]);
}

TEST(ClassCollisionExchange, ParticlesAsParcelsOfOneGetNoForce) {
  Box box;
  const Mixture parcels(500, 1.0, {0.0, 0.0, 0.0}, {0.08, 0.04, 0.08}, 3 + box.rank);
  for (double f : classCollisionForces(box, parcels, "gaussian", {0.97, 0.1}, 0.45, 1e-4).force)
    EXPECT_NEAR(f, 0.0, 1e-18);
}
