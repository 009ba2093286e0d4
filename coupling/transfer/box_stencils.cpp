#include "coupling/transfer/box_stencils.hpp"

#include <algorithm>
#include <climits>
#include <type_traits>
#include <variant>

namespace parcelflow::coupling {

void FluidCells::buildTable() {
  const std::size_t sx = cells_[0] + 1, sy = cells_[1] + 1;
  notWholeBelow_.assign(sx * sy * (cells_[2] + 1), 0);
  auto at = [&](int i, int j, int k) -> long& { return notWholeBelow_[(k * sy + j) * sx + i]; };
  for (int k = 0; k < cells_[2]; ++k)
    for (int j = 0; j < cells_[1]; ++j)
      for (int i = 0; i < cells_[0]; ++i)
        at(i + 1, j + 1, k + 1) = (kind_[index(i, j, k)] == kWhole ? 0 : 1) + at(i, j + 1, k + 1) +
                                  at(i + 1, j, k + 1) + at(i + 1, j + 1, k) - at(i, j, k + 1) - at(i, j + 1, k) -
                                  at(i + 1, j, k) + at(i, j, k);
}

bool FluidCells::allWhole(const Window& w) const {
  const std::size_t sx = cells_[0] + 1, sy = cells_[1] + 1;
  auto at = [&](int i, int j, int k) { return notWholeBelow_[(k * sy + j) * sx + i]; };
  const int i0 = w.lo[0], j0 = w.lo[1], k0 = w.lo[2];
  const int i1 = i0 + w.n[0], j1 = j0 + w.n[1], k1 = k0 + w.n[2];
  const long notWhole = at(i1, j1, k1) - at(i0, j1, k1) - at(i1, j0, k1) - at(i1, j1, k0) + at(i0, j0, k1) +
                        at(i0, j1, k0) + at(i1, j0, k0) - at(i0, j0, k0);
  return notWhole == 0;
}

namespace {

// Sum of the window's weights times the cells' fluid shares (0 if it has no fluid cell).
double fluidSum(const Window& w, const FluidCells& fluid) {
  if (fluid.allWhole(w)) {
    double s[3] = {0.0, 0.0, 0.0};
    for (int d = 0; d < 3; ++d)
      for (int a = 0; a < w.n[d]; ++a) s[d] += w.f[d][a];
    return s[0] * s[1] * s[2];
  }
  double sum = 0.0;
  for (int c = 0; c < w.n[2]; ++c)
    for (int b = 0; b < w.n[1]; ++b)
      for (int a = 0; a < w.n[0]; ++a)
        sum += fluid.fluidFraction(w.lo[0] + a, w.lo[1] + b, w.lo[2] + c) * w.f[0][a] * w.f[1][b] * w.f[2][c];
  return sum;
}

template <class Kernel>
TransferStats buildWith(const Kernel& kernel, const BackgroundGrid& grid, const FluidCells& fluid, std::size_t n,
                        const double* pos, const double* diameter, BoxStencils& out) {
  out.windows.resize(n);
  out.first.assign(n, -1);
  int lo[3] = {INT_MAX, INT_MAX, INT_MAX}, hi[3] = {INT_MIN, INT_MIN, INT_MIN};
  const auto fluidShare = [&](int i, int j, int k) { return fluid.fluidFraction(i, j, k); };
  TransferStats stats;
  for (std::size_t p = 0; p < n; ++p) {
    Window& w = out.windows[p];
    StencilResult r = kernel.window(grid, pos + 3 * p, diameter ? diameter[p] : 0.0, fluidShare, w);
    if (r != StencilResult::orphan) {
      const double sum = fluidSum(w, fluid);
      if (sum > 0.0) {
        for (int c = 0; c < w.n[2]; ++c) w.f[2][c] /= sum;
        out.first[p] = 0;  // a valid window; its box index follows once the box is known
        for (int d = 0; d < 3; ++d) {
          lo[d] = std::min(lo[d], w.lo[d]);
          hi[d] = std::max(hi[d], w.lo[d] + w.n[d] - 1);
        }
      } else {
        r = StencilResult::orphan;
      }
    }
    stats.record(p, r);
  }
  const bool empty = lo[0] > hi[0];
  for (int d = 0; d < 3; ++d) {
    out.lo[d] = empty ? 0 : lo[d];
    out.cells[d] = empty ? 0 : hi[d] - lo[d] + 1;
  }
  for (std::size_t p = 0; p < n; ++p)
    if (out.first[p] == 0) out.first[p] = out.boxIndex(out.windows[p].lo[0], out.windows[p].lo[1], out.windows[p].lo[2]);
  return stats;
}

// The loops run along each window row, which is contiguous in the box arrays: a row of n[0] cells is
// one stretch of n[0] ncomp doubles, updated by one multiply-add loop (the x factors are folded into
// the parcel's values first). Width > 0: the component count is known at compile time; Width = 0
// reads it from `ncomp`.
// One parcel's window rows with a compile-time row length (NX cells of Width components) where both are
// known (the loop then unrolls and vectorises); NX = 0 or Width = 0: run-time lengths.
template <int Width, int NX>
void depositOne(const Window& w, std::size_t ncomp, const double* qp, double* box, std::size_t sy, std::size_t sz) {
  const std::size_t nc = Width > 0 ? static_cast<std::size_t>(Width) : ncomp;
  const std::size_t nx = NX > 0 ? static_cast<std::size_t>(NX) : static_cast<std::size_t>(w.n[0]);
  double xq[Window::maxWidth * (Width > 0 ? Width : 8)];  // f_x[a] q[m] at a nc + m
  std::vector<double> wide;
  double* xqp = xq;
  if (Width == 0 && nc > 8) {
    wide.resize(Window::maxWidth * nc);
    xqp = wide.data();
  }
  for (std::size_t a = 0; a < nx; ++a)
    for (std::size_t m = 0; m < nc; ++m) xqp[nc * a + m] = w.f[0][a] * qp[m];
  const std::size_t len = nc * nx;
  for (int c = 0; c < w.n[2]; ++c)
    for (int b = 0; b < w.n[1]; ++b) {
      const double wzy = w.f[2][c] * w.f[1][b];
      double* row = box + c * sz + b * sy;
      for (std::size_t e = 0; e < len; ++e) row[e] += wzy * xqp[e];
    }
}

template <int Width, int NX>
void gatherOne(const Window& w, std::size_t ncomp, const double* box, double* out, std::size_t sy, std::size_t sz) {
  const std::size_t nc = Width > 0 ? static_cast<std::size_t>(Width) : ncomp;
  const std::size_t nx = NX > 0 ? static_cast<std::size_t>(NX) : static_cast<std::size_t>(w.n[0]);
  double rows[Window::maxWidth * (Width > 0 ? Width : 8)] = {};  // sum over the rows of f_z f_y value
  std::vector<double> wide;
  double* rowsp = rows;
  if (Width == 0 && nc > 8) {
    wide.assign(Window::maxWidth * nc, 0.0);
    rowsp = wide.data();
  }
  const std::size_t len = nc * nx;
  for (int c = 0; c < w.n[2]; ++c)
    for (int b = 0; b < w.n[1]; ++b) {
      const double wzy = w.f[2][c] * w.f[1][b];
      const double* row = box + c * sz + b * sy;
      for (std::size_t e = 0; e < len; ++e) rowsp[e] += wzy * row[e];
    }
  for (std::size_t m = 0; m < nc; ++m) {
    double sum = 0.0;
    for (std::size_t a = 0; a < nx; ++a) sum += w.f[0][a] * rowsp[nc * a + m];
    out[m] = sum;
  }
}

// Calls f(integral_constant<int, NX>) with NX = n for the window widths of R <= 2 (1 to 5), else NX = 0.
template <class F>
void withRowCells(int n, F&& f) {
  switch (n) {
    case 1: return f(std::integral_constant<int, 1>{});
    case 2: return f(std::integral_constant<int, 2>{});
    case 3: return f(std::integral_constant<int, 3>{});
    case 4: return f(std::integral_constant<int, 4>{});
    case 5: return f(std::integral_constant<int, 5>{});
    default: return f(std::integral_constant<int, 0>{});
  }
}

template <int Width>
void depositLoop(const BoxStencils& set, std::size_t ncomp, const double* q, double* boxQ) {
  const std::size_t nc = Width > 0 ? static_cast<std::size_t>(Width) : ncomp;
  const std::size_t sy = nc * set.cells[0], sz = sy * set.cells[1];
  for (std::size_t p = 0; p < set.parcels(); ++p) {
    if (set.first[p] < 0) continue;
    const Window& w = set.windows[p];
    double* box = boxQ + nc * static_cast<std::size_t>(set.first[p]);
    withRowCells(w.n[0], [&](auto nx) { depositOne<Width, nx()>(w, nc, q + nc * p, box, sy, sz); });
  }
}

template <int Width>
void gatherLoop(const BoxStencils& set, std::size_t ncomp, const double* boxQ, double* parcelQ,
                double orphanValue) {
  const std::size_t nc = Width > 0 ? static_cast<std::size_t>(Width) : ncomp;
  const std::size_t sy = nc * set.cells[0], sz = sy * set.cells[1];
  for (std::size_t p = 0; p < set.parcels(); ++p) {
    double* out = parcelQ + nc * p;
    if (set.first[p] < 0) {
      for (std::size_t m = 0; m < nc; ++m) out[m] = orphanValue;
      continue;
    }
    const Window& w = set.windows[p];
    const double* box = boxQ + nc * static_cast<std::size_t>(set.first[p]);
    withRowCells(w.n[0], [&](auto nx) { gatherOne<Width, nx()>(w, nc, box, out, sy, sz); });
  }
}

// Calls loop(integral_constant<int, W>) with W = ncomp for the widths the coupler uses, else W = 0.
template <class Loop>
void withWidth(int ncomp, Loop&& loop) {
  switch (ncomp) {
    case 1: return loop(std::integral_constant<int, 1>{});
    case 2: return loop(std::integral_constant<int, 2>{});
    case 4: return loop(std::integral_constant<int, 4>{});
    case 6: return loop(std::integral_constant<int, 6>{});
    default: return loop(std::integral_constant<int, 0>{});
  }
}

}  // namespace

TransferStats buildBoxStencils(const TransferKernel& kernel, const BackgroundGrid& grid, const FluidCells& fluid,
                               std::size_t n, const double* pos, BoxStencils& out, const double* diameter) {
  return std::visit([&](const auto& k) { return buildWith(k, grid, fluid, n, pos, diameter, out); }, kernel);
}

void deposit(const BoxStencils& set, int ncomp, const double* q, double* boxQ) {
  withWidth(ncomp, [&](auto width) { depositLoop<width()>(set, static_cast<std::size_t>(ncomp), q, boxQ); });
}

void gather(const BoxStencils& set, int ncomp, const double* boxQ, double* parcelQ, double orphanValue) {
  withWidth(ncomp, [&](auto width) {
    gatherLoop<width()>(set, static_cast<std::size_t>(ncomp), boxQ, parcelQ, orphanValue);
  });
}

}  // namespace parcelflow::coupling
