#pragma once
// Gaussian particle <-> mesh kernel (paper eq. 8; DESIGN.md section 4).
// Reference: Braun, Srinivasa, Gohel, "Validation of an efficient CFD-DEM model for large scale
// fluidized beds", eq. (8), after Apte (2008) and Kaufmann (2008):
//   w ~ exp(-a |x_cell - x_p|^2 / h^2),  a = 1 by default.
// On the Cartesian background the kernel is separable: w = fx fy fz with fx = exp(-a_x tx^2), tx = dx / hx
// the distance in cell lengths of that axis. h is one length, the cube root of the cell volume (the
// paper's "characteristic length scale of the cell"; case default): a_x = a (hx / h)^2, the same width in
// metres along every axis; or the cell's length along each axis (a_x = a: as many cells wide along every
// axis, so tall cells smooth vertically over more metres). The two agree on cubic cells. The kernel is
// truncated to +-R cells per axis around the cell containing the parcel (R = 2 by default, at most 4); the
// box stencils renormalise it over the fluid cells of that window, so sum w = 1 exactly: volume and
// momentum are conserved also next to walls. The prefactor (a/pi)^1.5 of eq. 8 cancels in the
// renormalisation.
// Parcels larger than the cell (coarse graining): with a parcel factor lambda > 0 a parcel of collision
// diameter D is spread over at least its own size, h_p = max(h, lambda D) along each axis, with the
// window widened in proportion (R_p = ceil(R h_p / h), at most maxRadius) so that it truncates the wider
// Gaussian as R truncates the cell's. A parcel of 2 cell volumes otherwise lands in 1-2 cells, and the
// gas-fraction floor is hit where they touch (cases/goldschmidt_segregation/README.md, "Coarse graining:
// causes"). lambda = 0 is eq. 8 as the paper wrote it; parcels with lambda D <= h are unaffected either way.
// Reflecting walls: the part of the Gaussian beyond a wall is given to the cells in front of it as an image
// parcel behind the wall puts it, instead of being dropped before the renormalisation. Walls are the faces of
// the background box and, inside it, where the parcel's row along an axis meets a cell without fluid (at the
// cut of a cut cell: findWalls). Evenly spread parcel centres then deposit evenly up to the wall, where
// truncation piles up 11 % more volume (tests/unit/transfer/deposition_test.cpp). In the settled Goldschmidt
// bed, whose centres keep D/2 off the walls, the wall cells get 0.87 of the middle cells' bead volume
// truncated, 0.94 reflected, and the beads themselves put 0.93 there.
#include <algorithm>
#include <cmath>

#include "coupling/transfer/background_grid.hpp"
#include "coupling/transfer/stencil.hpp"

namespace parcelflow::coupling {

class GaussianKernel {
 public:
  static constexpr const char* typeName = "gaussian";
  static constexpr int maxRadius = 4;
  static_assert(2 * maxRadius + 1 <= Window::maxWidth);

  // h per axis. Requires a > 0 and 0 <= radius <= maxRadius (PARCELFLOW_ASSERT).
  explicit GaussianKernel(double sharpness = 1.0, int radius = 2);
  // h = (hx hy hz)^(1/3) of cells of `spacing` (each > 0).
  GaussianKernel(double sharpness, int radius, const double (&spacing)[3]);
  // Either length scale, parcels wider than lambda D = h spread over h_p = lambda D (lambda >= 0), and the
  // background's faces reflecting (image parcels) or truncating the kernel.
  GaussianKernel(double sharpness, int radius, const double (&spacing)[3], bool isotropic, double parcelFactor,
                 bool reflectAtWalls = false);

  double sharpness() const { return a_; }
  // a_d: the sharpness along axis d in that axis' cell lengths
  double axisSharpness(int d) const { return axisA_[d]; }
  int radius() const { return r_; }
  double parcelFactor() const { return parcelFactor_; }
  // whether window() reads the parcel's diameter (only to widen the kernel for large parcels)
  bool readsDiameter() const { return parcelFactor_ > 0.0; }
  bool reflectsAtWalls() const { return reflect_; }

  // Mass fraction of the untruncated 1-D lattice kernel (all cells of an infinite row) that lies in
  // the +-R stencil, for a parcel at `offset` cell lengths from the centre of its cell (|offset| <= 1/2).
  // The 3-D fraction is the product over the axes.
  static double retainedMassFraction1D(double sharpness, int radius, double offset);

  // The window of a parcel at x with collision diameter `diameter` (read only with a parcel factor): +-R
  // cells around its cell, clipped to the background (fluid or not: the renormalisation over fluid cells is
  // the caller's); reflecting, also clipped at the walls of findWalls, which reads fluidShare(i, j, k) in
  // [0, 1] (truncating, it is not read). Orphan beyond R cells outside the box.
  template <class FluidShare>
  StencilResult window(const BackgroundGrid& g, const double* x, double diameter, const FluidShare& fluidShare,
                       Window& w) const {
    const double parcelLength = parcelFactor_ * diameter;
    double a[3], expMinus2a[3], xi[3];
    int r[3], ic[3];
    for (int d = 0; d < 3; ++d) {
      a[d] = axisA_[d];
      expMinus2a[d] = expMinus2a_[d];
      r[d] = r_;
      const double length = isotropicLength_ > 0.0 ? isotropicLength_ : g.spacing[d];
      if (parcelLength > length) {  // a parcel wider than the cell's kernel
        const double cellsPerLength = g.spacing[d] / parcelLength;
        a[d] = a_ * cellsPerLength * cellsPerLength;
        expMinus2a[d] = std::exp(-2.0 * a[d]);
        r[d] = std::min(maxRadius, static_cast<int>(std::ceil(r_ * parcelLength / length - 1e-9)));
      }
      xi[d] = (x[d] - g.origin[d]) / g.spacing[d];  // position in cell units
      // also rejects NaN: no stencil cell can exist beyond r cells outside the box
      if (!(xi[d] > -r[d] - 1.0 && xi[d] < g.cells[d] + r[d] + 1.0)) return StencilResult::orphan;
      // reflecting faces: a parcel and its mirror image have the same folded window
      if (reflect_) xi[d] = foldIntoBox(xi[d], g.cells[d]);
      ic[d] = std::min(static_cast<int>(std::floor(xi[d])), g.cells[d] - 1);
      if (ic[d] + r[d] < 0 || ic[d] - r[d] > g.cells[d] - 1) return StencilResult::orphan;
    }
    double walls[3][2];
    if (reflect_) findWalls(g, ic, r, xi, fluidShare, walls);
    for (int d = 0; d < 3; ++d) {
      int lo = std::max(ic[d] - r[d], 0), hi = std::min(ic[d] + r[d], g.cells[d] - 1);
      if (reflect_) {  // the cells of the parcel's side of the walls
        lo = std::max(lo, static_cast<int>(std::floor(walls[d][0])));
        hi = std::min(hi, static_cast<int>(std::ceil(walls[d][1])) - 1);
      }
      w.lo[d] = lo;
      w.n[d] = hi - lo + 1;
      // exp(-a t^2) at t = t0 + m, m = -r..r, from the centre outwards with 3 exponentials: the ratio of
      // neighbours is exp(-a (2 t + 1)) upwards, and each ratio is exp(-2a) times the previous one.
      // All ratios are <= 1 (|t0| <= 1/2), so far factors underflow to 0 as exp itself would.
      const int rd = r[d];
      const double t0 = (ic[d] + 0.5) - xi[d];
      double f[Window::maxWidth];
      f[rd] = std::exp(-a[d] * t0 * t0);
      double up = std::exp(-a[d] * (2.0 * t0 + 1.0)), down = std::exp(-a[d] * (1.0 - 2.0 * t0));
      for (int m = 1; m <= rd; ++m) {
        f[rd + m] = f[rd + m - 1] * up;
        f[rd - m] = f[rd - m + 1] * down;
        up *= expMinus2a[d];
        down *= expMinus2a[d];
      }
      for (int i = lo; i <= hi; ++i) w.f[d][i - lo] = f[i - ic[d] + rd];
      if (reflect_) addImages(xi[d], walls[d][0], walls[d][1], a[d], rd, lo, hi, w.f[d]);
    }
    return StencilResult::ok;
  }

 private:
  // x (cell units) mirrored at the faces 0 and n until it lies in [0, n]
  static double foldIntoBox(double x, int n) {
    while (x < 0.0 || x > n) x = x < 0.0 ? -x : 2.0 * n - x;
    return x;
  }

  // The walls that reflect the kernel along each axis, in cell units: walls[d] = {lower, upper}, the fluid of the
  // parcel's row along d lying between them. A wall is where that row, followed from the parcel's cell for up to
  // r cells, meets a cell with no fluid: at that cell's face, or inside the cut cell before it, at its fluid
  // share of the cell (the plane across d that leaves that share fluid); the box's faces otherwise. Cells
  // beyond a wall in other rows are treated as if the wall ran on there as a plane. A parcel in a cell without
  // fluid (a staircase corner) has the box's faces only; a parcel beyond the estimated wall gets it at itself.
  template <class FluidShare>
  static void findWalls(const BackgroundGrid& g, const int (&ic)[3], const int (&r)[3], const double (&xi)[3],
                        const FluidShare& fluidShare, double (&walls)[3][2]) {
    const bool inBox = ic[0] >= 0 && ic[1] >= 0 && ic[2] >= 0;
    const bool ownCellFluid = inBox && fluidShare(ic[0], ic[1], ic[2]) > 0.0;
    for (int d = 0; d < 3; ++d) {
      walls[d][0] = 0.0;
      walls[d][1] = g.cells[d];
      if (!ownCellFluid) continue;
      for (int side = 0; side < 2; ++side) {  // lower, then upper
        const int step = side == 0 ? -1 : 1;
        int cell[3] = {ic[0], ic[1], ic[2]};
        double share = fluidShare(ic[0], ic[1], ic[2]);  // of the last fluid cell met
        for (int m = 1; m <= r[d]; ++m) {
          cell[d] = ic[d] + step * m;
          if (cell[d] < 0 || cell[d] >= g.cells[d]) break;
          const double next = fluidShare(cell[0], cell[1], cell[2]);
          if (next <= 0.0) {
            // the face between the last fluid cell and this one, moved back into that cell by its solid share
            const double face = side == 0 ? cell[d] + 1 : cell[d];
            const double wall = face - step * (1.0 - share);
            walls[d][side] = side == 0 ? std::min(wall, xi[d]) : std::max(wall, xi[d]);
            break;
          }
          share = next;
        }
      }
    }
  }

  // Adds to f[i - lo], cells lo..hi, the weights of the parcel's images in the walls lower and upper (cell
  // units): each image (and image of an image, for windows wider than the gap between the walls) weighs the
  // cells of its own +-r window as the parcel weighs its own. At a wall on a cell face this is the parcel's
  // weight of each cell beyond it folded onto the mirror cell.
  static constexpr int kMaxReflections = 16;
  static void addImages(double xi, double lower, double upper, double a, int r, int lo, int hi, double* f) {
    for (int first = 0; first < 2; ++first) {
      double image = xi;
      for (int reflection = 0;; ++reflection) {
        const bool atUpper = (reflection % 2 == 0) == (first == 0);
        image = 2.0 * (atUpper ? upper : lower) - image;
        const int cell = static_cast<int>(std::floor(image));
        const int from = std::max(lo, cell - r), to = std::min(hi, cell + r);
        // further images are further away; walls closer than a few cells' hundredths end it as well
        if (from > to || reflection == kMaxReflections) break;
        for (int i = from; i <= to; ++i) {
          const double t = i + 0.5 - image;
          f[i - lo] += std::exp(-a * t * t);
        }
      }
    }
  }

  double a_;
  int r_;
  double axisA_[3], expMinus2a_[3];
  double isotropicLength_ = 0.0;  // h [m] of the cell_volume length scale; 0: the cell length per axis
  double parcelFactor_ = 0.0;     // lambda; 0: the cell's kernel for every parcel (eq. 8)
  bool reflect_ = false;          // the background's faces mirror the kernel instead of truncating it
};

}  // namespace parcelflow::coupling
