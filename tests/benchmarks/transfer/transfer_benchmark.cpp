// Particle <-> mesh transfer throughput: 100k parcels in a 40 x 40 x 80 all-fluid box, Gaussian
// (a = 1, R = 2 and R = 1) vs cell-centroid. Reports parcels per second for
//   build  : computing the box stencils the coupler uses (kernel windows, renormalisation),
//   deposit: deposit of (kappa, kappa v) from the box stencils,
//   gather : 6-component gather (gas velocity and pressure gradient) from the box stencils,
//   oracle : the ghost-deposition test oracle's depositParcels + gatherToParcels, recomputing the
//            weights each time through a dense local-index lookup (the uncached baseline).
// Not a test: prints numbers; label benchmark (excluded from the default ctest run).
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include "coupling/transfer/box_stencils.hpp"
#include "tests/support/ghost_deposition_oracle.hpp"

using namespace parcelflow::coupling;
using Clock = std::chrono::steady_clock;

namespace {

double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

template <class F>
double best(int reps, F&& f) {
  double t = 1e300;
  for (int r = 0; r < reps; ++r) {
    const auto a = Clock::now();
    f();
    t = std::min(t, seconds(a, Clock::now()));
  }
  return t;
}

}  // namespace

int main() {
  BackgroundGrid g;
  g.cells = {40, 40, 80};
  g.spacing = {0.01, 0.01, 0.01};
  const int nCells = g.cells[0] * g.cells[1] * g.cells[2];
  std::vector<int> index(nCells);
  for (int c = 0; c < nCells; ++c) index[c] = c;
  const auto lookup = [&](int i, int j, int k) { return index[(k * g.cells[1] + j) * g.cells[0] + i]; };
  const FluidCells fluid(g, [](int, int, int) { return true; });

  const std::size_t n = 100000;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> pos(3 * n), v(3 * n), kappa(n);
  for (std::size_t p = 0; p < n; ++p) {
    for (int d = 0; d < 3; ++d) {
      pos[3 * p + d] = u(rng) * g.cells[d] * g.spacing[d];
      v[3 * p + d] = u(rng) - 0.5;
    }
    kappa[p] = 1e-6 * (1 + u(rng));
  }
  // The coupler's widest transfers: kappa and kappa v to the cells, u and grad p to the parcels.
  std::vector<double> gasCell(6 * nCells, 0.3), gasP(6 * n), q(4 * n), cQ(4 * nCells);
  for (std::size_t p = 0; p < n; ++p) {
    q[4 * p] = kappa[p];
    for (int d = 0; d < 3; ++d) q[4 * p + 1 + d] = kappa[p] * v[3 * p + d];
  }

  std::printf("transfer benchmark: %zu parcels, %d cells, best of 5 (parcels per second, millions)\n", n, nCells);
  std::printf("%-20s %10s %10s %10s %12s %10s\n", "kernel", "build", "deposit", "gather", "oracle d+g", "cells/parcel");
  const TransferKernel kernels[] = {GaussianKernel(1.0, 2), GaussianKernel(1.0, 1), CentroidKernel(1)};
  const char* names[] = {"gaussian a=1 R=2", "gaussian a=1 R=1", "centroid"};
  for (int k = 0; k < 3; ++k) {
    BoxStencils set;
    const double tBuild = best(5, [&] { buildBoxStencils(kernels[k], g, fluid, n, pos.data(), set); });
    if (set.boxSize() != nCells) {  // the arrays below are laid out on the whole grid
      std::printf("box of %ld cells, expected the whole grid\n", set.boxSize());
      return 1;
    }
    double windowCells = 0.0;
    for (const Window& w : set.windows) windowCells += w.n[0] * w.n[1] * w.n[2];
    const double tDep = best(5, [&] { deposit(set, 4, q.data(), cQ.data()); });
    const double tGat = best(5, [&] { gather(set, 6, gasCell.data(), gasP.data()); });
    const double tOracle = best(5, [&] {
      test::depositParcels(kernels[k], g, lookup, n, pos.data(), 4, q.data(), cQ.data());
      test::gatherToParcels(kernels[k], g, lookup, n, pos.data(), 6, gasCell.data(), gasP.data());
    });
    std::printf("%-20s %10.2f %10.2f %10.2f %12.2f %10.1f\n", names[k], n / tBuild * 1e-6, n / tDep * 1e-6,
                n / tGat * 1e-6, n / tOracle * 1e-6, windowCells / n);
  }
  return 0;
}
