#include "cfd/mesh/cell_groups.hpp"

namespace parcelflow::cfd {

namespace {

// The neighbour of background cell b across its largest open face among those `joinable` accepts (the
// lowest background index on a tie), -1 when there is none.
template <class Joinable>
long largestOpenNeighbour(const CartesianBackground& bg, const CutCellGeometry& cut, long b, const Joinable& joinable) {
  const auto ijk = bg.ijk(b);
  long best = -1;
  double bestOpen = 0.0;
  for (int f = 0; f < 6; ++f) {
    auto n = ijk;
    n[f / 2] += f % 2 ? 1 : -1;
    if (!bg.inside(n[0], n[1], n[2])) continue;
    const long nb = bg.index(n[0], n[1], n[2]);
    const double open = cut.openFraction(b, static_cast<CellFace>(f));
    if (!joinable(nb) || open <= 0.0) continue;
    if (open > bestOpen || (open == bestOpen && nb < best)) {
      best = nb;
      bestOpen = open;
    }
  }
  return best;
}

}  // namespace

CellGroups groupCells(const CartesianBackground& bg, const std::vector<bool>& fluid, const CutCellGeometry* cut,
                      double smallFraction) {
  CellGroups g;
  const long nBg = bg.size();
  std::vector<long> master(nBg, -1);  // the background cell whose group b belongs to
  std::vector<long> alone;            // small cells with no open face to a cell that is not small
  for (long b = 0; b < nBg; ++b) {
    if (!fluid[b]) continue;
    master[b] = b;
    if (!cut || cut->fluidFraction(b) >= smallFraction) continue;
    const long m = largestOpenNeighbour(bg, *cut, b, [&](long nb) { return cut->fluidFraction(nb) >= smallFraction; });
    if (m >= 0) {
      master[b] = m;
      ++g.mergedCells;
    } else {
      alone.push_back(b);
    }
  }
  // A small cell whose open faces all lead to small cells (a sliver in a corner of other cut cells) joins
  // the group of a neighbour that has joined one, in rounds until none is left that can: its group is then
  // connected through its members' faces rather than all through the master's.
  for (bool joined = true; joined && !alone.empty();) {
    joined = false;
    std::vector<long> still;
    for (long b : alone) {
      const long nb = largestOpenNeighbour(bg, *cut, b, [&](long n) { return master[n] >= 0 && master[n] != n; });
      if (nb >= 0) {
        master[b] = master[nb];
        ++g.mergedCells;
        joined = true;
      } else {
        still.push_back(b);
      }
    }
    alone.swap(still);
  }
  g.unmergedSmallCells = static_cast<long>(alone.size());
  g.globalOfBackground.assign(nBg, -1);
  for (long b = 0; b < nBg; ++b)
    if (master[b] == b) {
      g.globalOfBackground[b] = static_cast<int>(g.backgroundOfGlobal.size());
      g.backgroundOfGlobal.push_back(b);
      g.members.push_back({b});
    }
  for (long b = 0; b < nBg; ++b)
    if (master[b] >= 0 && master[b] != b) {
      const int id = g.globalOfBackground[master[b]];
      g.globalOfBackground[b] = id;
      g.members[id].push_back(b);
    }
  return g;
}

FluidRegions fluidRegions(const CartesianBackground& bg, const CellGroups& groups, const CutCellGeometry* cut) {
  const int nGlobal = static_cast<int>(groups.backgroundOfGlobal.size());
  FluidRegions r;
  r.ofGlobal.assign(nGlobal, -1);
  std::vector<int> stack;
  for (int seed = 0; seed < nGlobal; ++seed) {
    if (r.ofGlobal[seed] >= 0) continue;
    const int region = static_cast<int>(r.cells.size());
    r.cells.push_back(0);
    r.firstGlobal.push_back(seed);
    r.ofGlobal[seed] = region;
    stack.push_back(seed);
    while (!stack.empty()) {
      const int g = stack.back();
      stack.pop_back();
      ++r.cells[region];
      for (long b : groups.members[g]) {
        const auto ijk = bg.ijk(b);
        for (int f = 0; f < 6; ++f) {
          auto n = ijk;
          n[f / 2] += f % 2 ? 1 : -1;
          if (!bg.inside(n[0], n[1], n[2])) continue;
          if (cut && cut->openFraction(b, static_cast<CellFace>(f)) <= 0.0) continue;
          const int ng = groups.globalOfBackground[bg.index(n[0], n[1], n[2])];
          if (ng < 0 || r.ofGlobal[ng] >= 0) continue;
          r.ofGlobal[ng] = region;
          stack.push_back(ng);
        }
      }
    }
  }
  return r;
}

}  // namespace parcelflow::cfd
