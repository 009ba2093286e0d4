#pragma once
// The stencils of a whole batch of parcels, computed once per coupling step and reused for every
// transfer of that step (deposit volume, gather a_g, u, grad p, deposit kappa and kappa v): the same
// weights both ways, so the force on the gas is minus the force on the parcels to round-off.
//
// Stored in separable form on a box of background cells, the bounding box of the batch's windows:
// per parcel its Window, whose z factors carry the renormalisation 1 / (sum over the window's fluid
// cells), and the box index of its first cell. Box arrays hold `ncomp` values per box cell, x fastest,
// so each window row is contiguous: no per-cell index is stored or looked up (a Gaussian R = 2 stencil
// is 27 factors instead of 125 (cell, weight) pairs). Non-fluid box cells: a deposit there is
// discarded and a gather must read 0 there; the weights over the fluid cells sum to 1, so volume and
// momentum are conserved exactly.
#include <array>
#include <cstddef>
#include <limits>
#include <vector>

#include "background_grid.hpp"
#include "stencil.hpp"
#include "transfer_kernel.hpp"

namespace parcelflow::coupling {

// Which background cells are fluid, with a summed-volume table so that "is this whole window fluid?"
// costs 8 lookups (then its renormalisation sum is the product of the per-axis sums).
class FluidCells {
 public:
  // isFluid(i, j, k) for every background cell, evaluated once here.
  template <class IsFluid>
  FluidCells(const BackgroundGrid& grid, const IsFluid& isFluid) : cells_(grid.cells) {
    fluid_.resize(static_cast<std::size_t>(cells_[0]) * cells_[1] * cells_[2]);
    for (int k = 0; k < cells_[2]; ++k)
      for (int j = 0; j < cells_[1]; ++j)
        for (int i = 0; i < cells_[0]; ++i) fluid_[index(i, j, k)] = isFluid(i, j, k) ? 1 : 0;
    buildTable();
  }

  bool isFluid(int i, int j, int k) const { return fluid_[index(i, j, k)] != 0; }
  bool allFluid(const Window& w) const;

 private:
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * cells_[1] + j) * cells_[0] + i;
  }
  void buildTable();
  std::array<int, 3> cells_;
  std::vector<unsigned char> fluid_;
  std::vector<long> nonFluidBelow_;  // (nx+1)(ny+1)(nz+1): non-fluid cells with i' < i, j' < j, k' < k
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
