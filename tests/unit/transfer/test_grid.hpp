#pragma once
// Test fixture: an anisotropic Cartesian background with an L-shaped active mask (a solid block
// i >= 6 && j >= 5 is cut out, so there are outer walls and a re-entrant inside corner), and a
// lookup that numbers active cells in a shuffled order with gaps, as owned + ghost numbering would.
#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include "coupling/transfer/background_grid.hpp"

namespace parcelflow::coupling::test {

struct MaskedGrid {
  BackgroundGrid grid;
  std::vector<int> local;                  // background (i,j,k) -> local index or -1
  std::vector<std::array<int, 3>> ijkOf;   // local index -> (i,j,k); (-1,..) for gaps
  int localSize = 0;

  int operator()(int i, int j, int k) const {
    return local[(static_cast<std::size_t>(k) * grid.cells[1] + j) * grid.cells[0] + i];
  }
  bool active(int i, int j, int k) const { return (*this)(i, j, k) >= 0; }
  double centre(int localCell, int d) const { return grid.cellCentre(d, ijkOf[localCell][d]); }
};

// lShaped = false gives an all-active box.
inline MaskedGrid makeGrid(std::array<int, 3> n, bool lShaped, unsigned seed = 7) {
  MaskedGrid g;
  g.grid.origin = {0.1, -0.2, 0.3};
  g.grid.spacing = {0.01, 0.02, 0.015};
  g.grid.cells = n;
  std::vector<std::array<int, 3>> act;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        if (!(lShaped && i >= 6 && j >= 5)) act.push_back({i, j, k});
  std::mt19937 rng(seed);
  std::shuffle(act.begin(), act.end(), rng);
  g.local.assign(static_cast<std::size_t>(n[0]) * n[1] * n[2], -1);
  // every 5th local index is a gap (never returned by the lookup), like non-neighbour cells on a rank
  int next = 0;
  for (const auto& c : act) {
    if (next % 5 == 4) {
      g.ijkOf.push_back({-1, -1, -1});
      ++next;
    }
    g.local[(static_cast<std::size_t>(c[2]) * n[1] + c[1]) * n[0] + c[0]] = next;
    g.ijkOf.push_back(c);
    ++next;
  }
  g.localSize = next;
  return g;
}

// Uniform random positions in the active region (the L), including its walls.
inline std::vector<double> randomActivePositions(const MaskedGrid& g, std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> pos;
  const auto& G = g.grid;
  while (pos.size() < 3 * n) {
    double x[3];
    int c[3];
    for (int d = 0; d < 3; ++d) {
      x[d] = G.origin[d] + u(rng) * G.cells[d] * G.spacing[d];
      c[d] = std::min(static_cast<int>((x[d] - G.origin[d]) / G.spacing[d]), G.cells[d] - 1);
    }
    if (!g.active(c[0], c[1], c[2])) continue;
    pos.insert(pos.end(), x, x + 3);
  }
  return pos;
}

}  // namespace parcelflow::coupling::test
