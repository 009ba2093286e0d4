// DiffusionSmoother: conservative to round-off, a uniform field unchanged, a spike spread as the discrete
// screened-Poisson kernel computed by hand, and the same answer on any number of ranks.
#include <gtest/gtest.h>
#include <mpi.h>

#include <array>
#include <cmath>
#include <vector>

#include "cfd/fv/diffusion_smoother.hpp"
#include "cfd/mesh/mesh_builder.hpp"
#include "tests/unit/cfd/same_on_rank_zero_alone.hpp"

using namespace parcelflow::cfd;

namespace {
Mesh mesh(Vec3 lengths, std::array<int, 3> cells) {
  MeshSettings s;
  s.lengths = lengths;
  s.cells = cells;
  return MeshBuilder::build(s, Geometry(), MPI_COMM_WORLD);
}

// A rough field, as a packed bed of parcels deposited into one or two cells each: a checkerboard of +-0.1 on
// a slow variation.
double rough(const Mesh& m, int c) {
  const Vec3& x = m.cellCentre(c);
  const Vec3& h = m.background().spacing();
  int parity = 0;
  for (int d = 0; d < 3; ++d) parity += static_cast<int>(x[d] / h[d]);
  parity %= 2;
  return 0.6 + (parity ? 0.1 : -0.1) + 0.05 * std::sin(97.0 * x[0]) * std::cos(61.0 * x[1] + 13.0 * x[2]);
}
}  // namespace

TEST(DiffusionSmoother, ConservesTheIntegralAndKeepsAUniformField) {
  const Mesh m = mesh(Vec3(0.075, 0.075, 0.15), {12, 12, 24});
  DiffusionSmoother smoother(m, 0.01);
  std::vector<double> s(m.nOwnedCells()), uniform(m.nOwnedCells(), 0.58);
  double before = 0.0, volume = 0.0, spreadBefore = 0.0;
  for (int c = 0; c < m.nOwnedCells(); ++c) {
    s[c] = rough(m, c);
    before += m.cellVolume(c) * s[c];
    volume += m.cellVolume(c);
  }
  before = m.sum(before);
  const double mean = before / m.sum(volume);
  for (int c = 0; c < m.nOwnedCells(); ++c) spreadBefore += (s[c] - mean) * (s[c] - mean);
  smoother.apply(s);
  double after = 0.0, spreadAfter = 0.0;
  for (int c = 0; c < m.nOwnedCells(); ++c) {
    after += m.cellVolume(c) * s[c];
    spreadAfter += (s[c] - mean) * (s[c] - mean);
  }
  EXPECT_NEAR(m.sum(after), before, 1e-12 * before);
  // the checkerboard's factor is 1 / (1 + 12 L^2/h^2) = 0.03 inside; the slow part stays
  EXPECT_LT(m.sum(spreadAfter), 0.1 * m.sum(spreadBefore));
  smoother.apply(uniform);
  for (double v : uniform) EXPECT_NEAR(v, 0.58, 1e-12);
}

TEST(DiffusionSmoother, SpreadsASpikeAsTheDiscreteScreenedPoissonKernel) {
  // A line of 201 cells of h = 1 mm: far from the ends, s_i = rho^|i| / sqrt(1 + 4k) / h-volume units.
  const double h = 1e-3, L = 2.5e-3, k = L * L / (h * h);
  const int n = 201, centre = 100;
  const Mesh m = mesh(Vec3(n * h, h, h), {n, 1, 1});
  DiffusionSmoother smoother(m, L);
  std::vector<double> s(m.nOwnedCells(), 0.0);
  for (int c = 0; c < m.nOwnedCells(); ++c)
    if (m.globalId(c) == centre) s[c] = 1.0;
  smoother.apply(s);
  const double rho = (1.0 + 2.0 * k - std::sqrt(1.0 + 4.0 * k)) / (2.0 * k);
  for (int c = 0; c < m.nOwnedCells(); ++c) {
    const int i = static_cast<int>(m.globalId(c)) - centre;
    if (std::abs(i) > 20) continue;  // the ends (100 cells away) change rho^100 ~ 1e-20 only; skip the tails
    EXPECT_NEAR(s[c], std::pow(rho, std::abs(i)) / std::sqrt(1.0 + 4.0 * k), 1e-11) << "cell offset " << i;
  }
}

TEST(DiffusionSmoother, GivesTheSameFieldOnAnyNumberOfRanks) {
  const Mesh m = mesh(Vec3(0.06, 0.03, 0.12), {10, 5, 20});
  DiffusionSmoother smoother(m, 0.008);
  std::vector<double> s(m.nOwnedCells());
  for (int c = 0; c < m.nOwnedCells(); ++c) s[c] = rough(m, c);
  smoother.apply(s);
  const std::vector<double> global = test::byGlobalId(m, s);
  // the same problem solved by rank 0 alone
  test::onRankZeroAlone([&](MPI_Comm self) {
    MeshSettings settings;
    settings.lengths = Vec3(0.06, 0.03, 0.12);
    settings.cells = {10, 5, 20};
    const Mesh alone = MeshBuilder::build(settings, Geometry(), self);
    DiffusionSmoother serial(alone, 0.008);
    std::vector<double> t(alone.nOwnedCells());
    for (int c = 0; c < alone.nOwnedCells(); ++c) t[c] = rough(alone, c);
    serial.apply(t);
    for (int c = 0; c < alone.nOwnedCells(); ++c) EXPECT_NEAR(global[alone.globalId(c)], t[c], 1e-10);
  });
}
