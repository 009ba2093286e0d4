#pragma once
// The stencils of a whole batch of parcels, computed once per coupling step and reused for every
// transfer of that step (deposit volume, gather a_g, u, grad p, deposit kappa and kappa v): the same
// weights both ways, so the force on the gas is minus the force on the parcels to round-off.
//
// Stored in separable form on a box of background cells, the bounding box of the batch's windows:
// per parcel its Window, whose z factors carry the renormalisation 1 / (sum over the window's cells of
// weight times fluid share), and the box index of its first cell. Box arrays hold `ncomp` values per box
// cell, x fastest, so each window row is contiguous: no per-cell index is stored or looked up (a Gaussian R = 2 stencil
// is 27 factors instead of 125 (cell, weight) pairs). Non-fluid box cells: a deposit there is
// discarded and a gather must read 0 there. A cell cut by a wall takes its fluid share f of what lands on
// it (the caller multiplies the box value by f both ways: deposit and gather); the weights times the
// shares sum to 1, so volume and momentum are conserved exactly.
#include <array>
#include <cstddef>
#include <limits>
#include <unordered_map>
#include <vector>

#include "coupling/transfer/background_grid.hpp"
#include "coupling/transfer/stencil.hpp"
#include "coupling/transfer/transfer_kernel.hpp"

namespace parcelflow::coupling {

// Which background cells are fluid and how much of each (cells cut by a wall hold a share below 1), with a
// summed-volume table so that "is every cell of this window whole fluid?" costs 8 lookups (then its
// renormalisation sum is the product of the per-axis sums).
class FluidCells {
 public:
  // fluidFraction(i, j, k) in [0, 1] for every background cell (a bool: whole or none), evaluated once here.
  template <class FluidFraction>
  FluidCells(const BackgroundGrid& grid, const FluidFraction& fluidFraction) : cells_(grid.cells) {
    kind_.resize(static_cast<std::size_t>(cells_[0]) * cells_[1] * cells_[2]);
    for (int k = 0; k < cells_[2]; ++k)
      for (int j = 0; j < cells_[1]; ++j)
        for (int i = 0; i < cells_[0]; ++i) {
          const double f = static_cast<double>(fluidFraction(i, j, k));
          const std::size_t c = index(i, j, k);
          kind_[c] = f >= 1.0 ? kWhole : f > 0.0 ? kCut : kNone;
          if (kind_[c] == kCut) cut_[c] = f;
        }
    buildTable();
  }

  bool isFluid(int i, int j, int k) const { return kind_[index(i, j, k)] != kNone; }
  double fluidFraction(int i, int j, int k) const {
    const std::size_t c = index(i, j, k);
    return kind_[c] == kWhole ? 1.0 : kind_[c] == kNone ? 0.0 : cut_.at(c);
  }
  // Every cell of the window is whole fluid.
  bool allWhole(const Window& w) const;

 private:
  static constexpr unsigned char kNone = 0, kCut = 1, kWhole = 2;
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * cells_[1] + j) * cells_[0] + i;
  }
  void buildTable();
  std::array<int, 3> cells_;
  std::vector<unsigned char> kind_;
  std::unordered_map<std::size_t, double> cut_;  // the fluid share of the cut cells
  std::vector<long> notWholeBelow_;  // (nx+1)(ny+1)(nz+1): cells not whole fluid with i' < i, j' < j, k' < k
};

struct BoxStencils {
  std::array<int, 3> lo{0, 0, 0};     // first background cell of the box
  std::array<int, 3> cells{0, 0, 0};  // box cells per axis (0 when every parcel is an orphan)
  std::vector<Window> windows;        // per parcel
  std::vector<long> first;            // per parcel: box index of the window's first cell, -1 = orphan

  std::size_t parcels() const { return first.size(); }
  long boxSize() const { return static_cast<long>(cells[0]) * cells[1] * cells[2]; }
  long boxIndex(int i, int j, int k) const {
    return (i - lo[0]) + static_cast<long>(cells[0]) * ((j - lo[1]) + static_cast<long>(cells[1]) * (k - lo[2]));
  }
};

// Fills `out` with the windows of the n parcels at pos (interleaved xyz), renormalised over fluid cells.
// diameter: the parcels' collision diameters, for a kernel that widens for large parcels (nullptr: none
// is read, as for parcels of diameter 0).
TransferStats buildBoxStencils(const TransferKernel& kernel, const BackgroundGrid& grid, const FluidCells& fluid,
                               std::size_t n, const double* pos, BoxStencils& out, const double* diameter = nullptr);

// boxQ[ncomp b + m] += w_pb q[ncomp p + m] over the box cells b of each parcel's window.
void deposit(const BoxStencils& set, int ncomp, const double* q, double* boxQ);

// parcelQ[ncomp p + m] = sum_b w_pb boxQ[ncomp b + m]; orphans get orphanValue.
void gather(const BoxStencils& set, int ncomp, const double* boxQ, double* parcelQ,
            double orphanValue = std::numeric_limits<double>::quiet_NaN());

}  // namespace parcelflow::coupling
