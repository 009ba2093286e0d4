#include <gtest/gtest.h>
#include <mpi.h>

#include <random>
#include <set>

#include "coupling/exchange/cell_exchange.h"

namespace pc = parcelflow::coupling;

namespace {

constexpr long kBackground = 97;
bool isFluid(long cell) { return cell % 7 != 3; }

// Fluid cells dealt to ranks in contiguous blocks, so owner-local order differs from background order.
std::vector<long> ownedCells(int rank, int nranks) {
  std::vector<long> mine;
  for (long c = kBackground - 1; c >= 0; --c)
    if (isFluid(c) && (c * nranks) / kBackground == rank) mine.push_back(c);
  return mine;
}

// What rank r contributes: a distinct set of fluid cells with values depending on (r, cell).
std::vector<long> touchedBy(int rank) {
  std::mt19937 rng(1234 + rank);
  std::set<long> cells;
  for (int n = 0; n < 40; ++n) {
    const long c = static_cast<long>(rng() % kBackground);
    if (isFluid(c)) cells.insert(c);
  }
  return {cells.begin(), cells.end()};
}
double contribution(int rank, long cell, int k) { return 1.0 + rank * 0.25 + cell * 1e-3 + k * 10.0; }

struct World {
  int rank = 0, nranks = 1;
  World() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &nranks);
  }
};

}  // namespace

TEST(CellExchange, SumsEveryContributionIntoItsOwnerExactlyOnce) {
  World w;
  const auto mine = ownedCells(w.rank, w.nranks);
  pc::CellOwnerMap owners(MPI_COMM_WORLD, kBackground, mine);
  pc::CellExchange exchange(owners);
  const int width = 3;
  const auto cells = touchedBy(w.rank);
  std::vector<double> values;
  for (long c : cells)
    for (int k = 0; k < width; ++k) values.push_back(contribution(w.rank, c, k));
  std::vector<double> owned(mine.size() * width, 0.0);
  exchange.setCells(cells);
  exchange.sumToOwners(values, width, owned);

  for (std::size_t i = 0; i < mine.size(); ++i) {
    for (int k = 0; k < width; ++k) {
      double expected = 0.0;
      for (int r = 0; r < w.nranks; ++r)
        for (long c : touchedBy(r))
          if (c == mine[i]) expected += contribution(r, c, k);
      EXPECT_DOUBLE_EQ(owned[i * width + k], expected) << "cell " << mine[i];
    }
  }
}

TEST(CellExchange, FetchReturnsTheOwnersValues) {
  World w;
  const auto mine = ownedCells(w.rank, w.nranks);
  pc::CellOwnerMap owners(MPI_COMM_WORLD, kBackground, mine);
  pc::CellExchange exchange(owners);
  std::vector<double> owned;
  for (long c : mine) owned.insert(owned.end(), {c * 1.5, -c * 0.5});
  const auto cells = touchedBy(w.rank);
  std::vector<double> fetched;
  exchange.setCells(cells);
  exchange.fetchFromOwners(owned, 2, fetched);
  ASSERT_EQ(fetched.size(), cells.size() * 2);
  for (std::size_t t = 0; t < cells.size(); ++t) {
    EXPECT_EQ(fetched[2 * t], cells[t] * 1.5);
    EXPECT_EQ(fetched[2 * t + 1], -cells[t] * 0.5);
  }
}

TEST(CellOwnerMap, KnowsEveryFluidCellAndNoOther) {
  World w;
  pc::CellOwnerMap owners(MPI_COMM_WORLD, kBackground, ownedCells(w.rank, w.nranks));
  for (long c = 0; c < kBackground; ++c) {
    EXPECT_EQ(owners.ownerRank(c) >= 0, isFluid(c)) << c;
    if (isFluid(c)) {
      EXPECT_EQ(owners.ownerRank(c), static_cast<int>((c * w.nranks) / kBackground));
    }
  }
}
