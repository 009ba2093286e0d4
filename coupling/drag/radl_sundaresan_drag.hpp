#pragma once
// Filtered (sub-grid) drag of Radl & Sundaresan: the BVK law reduced for the particle clusters that a coarse
// gas grid does not resolve.
// Reference: S. Radl, S. Sundaresan, "A drag model for filtered Euler-Lagrange simulations of clustered
// gas-particle suspensions", Chem. Eng. Sci. 117 (2014) 416-425. The paper's text was not available here, so
// no equation numbers: the form and the fitted coefficients were read in the open implementation
// CFDEMcoupling-PFM, src/lagrangian/cfdemParticle/subModels/forceModel/BeetstraDrag/BeetstraDrag.C (its
// "useFilteredDragModel" branch and the functions a() and h(), which it attributes to this paper):
//   K = (1 - H) K_BVK,   H = h(phi) x / (a(phi) + x),   phi = a_s,
//   x = Delta* Fr_p^(2/3),   Delta* = Delta g / v_t^2,   Fr_p = v_t^2 / (g d_p),
// so x = Delta / L with L = (v_t^2/g) Fr_p^(-2/3) = (v_t^2 d_p^2 / g)^(1/3). h(phi) is the correction of an
// infinitely large filter, a(phi) the x at which half of it is reached; both are piecewise cubics (below).
// Limits: H -> 0 as Delta -> 0 (x -> 0) and as phi -> 0 (h = 7.97 phi).
// Our choices and assumptions:
// - the microscopic law is BVK with its polydisperse correction (beetstra_drag.hpp), as in CFDEMcoupling-PFM;
// - v_t is the terminal velocity of ONE real particle of the parcel's own diameter d_p under the same BVK
//   law at phi = 0 in the case's gas, with one particle density per case (DragLawContext);
// - Delta is the gas cell size (V_cell)^(1/3) of the uniform background grid (DragLawContext);
// - where h < 0 (phi > 0.600: the last fitted cubic falls below 0 beyond dense packing) H = 0, i.e. the
//   microscopic drag; each such evaluation is counted (DragStats::filterCorrectionClamped). Elsewhere
//   0 <= h <= 0.947, so 1 - H >= 0.053: the drag stays positive;
// - not used: CFDEMcoupling-PFM's parcel-size factor exp(k (1 - D/d_p)), k = 0.05
//   ("useParcelSizeDependentFilteredDrag"): at this project's D/d_p = 50 .. 3000 it would scale the drag
//   by 0.08 .. 1e-65, an extrapolation we do not trust.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "coupling/drag/beetstra_drag.hpp"
#include "coupling/drag/drag_input.hpp"

namespace parcelflow::coupling {

namespace radl_sundaresan_detail {

inline constexpr double kNoUpperBound = std::numeric_limits<double>::infinity();  // the last segment

// c0 + c1 t + c2 t^2 + c3 t^3, t = phi - centre, for phi below `upper` (the first matching segment).
struct CubicSegment {
  double upper, centre, c0, c1, c2, c3;
};

// h(phi) and a(phi), coefficients as in CFDEMcoupling-PFM's BeetstraDrag.C.
inline constexpr CubicSegment kLargeFilterCorrection[] = {
    {0.03, 0.00, 0.000, 7.970, 0.000, 0.000},      {0.08, 0.03, 0.239, 4.640, -4.410, 253.630},
    {0.12, 0.08, 0.492, 6.100, 33.630, -789.600},  {0.18, 0.12, 0.739, 5.010, -61.100, 310.800},
    {0.34, 0.18, 0.887, 1.030, -5.170, 5.990},     {0.48, 0.34, 0.943, -0.170, -2.290, -9.120},
    {0.55, 0.48, 0.850, -1.350, -6.130, -132.600}, {kNoUpperBound, 0.55, 0.680, -2.340, -225.200, 0.000}};
inline constexpr CubicSegment kHalfCorrectionFilterSize[] = {
    {0.016, 0.00, 21.51, 0.00, 0.00, 0.00},     {0.10, 0.00, 1.96, 29.40, 164.91, -1923.00},
    {0.18, 0.10, 4.63, 4.68, -412.04, 2254.00}, {0.25, 0.18, 3.52, -17.99, 128.80, -603.00},
    {0.40, 0.25, 2.68, -8.20, 2.18, 112.33},    {kNoUpperBound, 0.00, 1.79, 0.00, 0.00, 0.00}};

template <std::size_t N>
double evaluate(const CubicSegment (&fit)[N], double phi) noexcept {
  std::size_t i = 0;
  while (i + 1 < N && !(phi < fit[i].upper)) ++i;
  const CubicSegment& s = fit[i];
  const double t = phi - s.centre;
  return s.c0 + t * (s.c1 + t * (s.c2 + t * s.c3));
}

}  // namespace radl_sundaresan_detail

class RadlSundaresanDrag {
 public:
  static constexpr const char* typeName = "RadlSundaresanFilteredBVK";
  static constexpr bool usesMeanDiameter = true;  // the BVK part reads DragInput::dMean
  static const char* reference();

  // Needs filterSize, gravity and particleDensity > 0 (the case reader checks them; InternalError otherwise).
  // The particle density must exceed the gas density of every evaluation (also checked by the reader).
  explicit RadlSundaresanDrag(const DragLawContext& context);

  // h(phi): H for an infinitely large filter.
  static double largeFilterCorrection(double phi) noexcept {
    return radl_sundaresan_detail::evaluate(radl_sundaresan_detail::kLargeFilterCorrection, phi);
  }
  // a(phi): the scaled filter size x at which H = h / 2.
  static double halfCorrectionFilterSize(double phi) noexcept {
    return radl_sundaresan_detail::evaluate(radl_sundaresan_detail::kHalfCorrectionFilterSize, phi);
  }

  // Re_t of one particle under BVK at phi = 0: Re_t F(0, Re_t) = stokesReynolds (= Ar/18, Stokes' law).
  // Newton on s = ln Re. G(s) = s + ln F(0, e^s) - ln stokesReynolds is increasing and convex, so from an
  // upper bound the iterates decrease monotonically onto the root. Upper bounds: F >= 1 gives Re_t <=
  // stokesReynolds, F >= c Re gives Re_t <= sqrt(stokesReynolds / c); start from the smaller. Quadratic
  // convergence: a step below 1e-8 leaves an error near 1e-16 (over stokesReynolds = 1e-12 .. 1e16 at most
  // 4 steps; the unit test checks the force balance there).
  static double terminalReynolds(double stokesReynolds) noexcept {
    constexpr double c = 0.413 / 24.0;
    const double target = std::log(stokesReynolds);
    double s = std::min(target, 0.5 * (target - std::log(c)));
    for (int step = 0; step < 50; ++step) {
      // F(0, Re) = 1 + c p, p = (Re + 8.4 Re^0.657) sqrt(Re) / (sqrt(Re) + 1) (beetstra_drag.hpp at phi = 0)
      const double re = std::exp(s), root = std::sqrt(re), rePow = std::exp(0.657 * s);
      const double sum = re + 8.4 * rePow;
      const double p = sum * root / (root + 1.0);
      const double f = 1.0 + c * p;
      const double dLnPdS = (re + 0.657 * 8.4 * rePow) / sum + 0.5 / (root + 1.0);
      const double ds = (s + std::log(f) - target) / (1.0 + c * p * dLnPdS / f);
      s -= ds;
      if (std::abs(ds) < 1e-8) break;
    }
    return std::exp(s);
  }

  // Terminal velocity v_t [m/s] of one particle of diameter in.dp in the gas of `in`.
  double terminalVelocity(const DragInput& in) const noexcept {
    const double stokesReynolds = in.rhoG * (particleDensity_ - in.rhoG) * gravity_ * in.dp * in.dp * in.dp /
                                  (18.0 * in.muG * in.muG);
    return terminalReynolds(stokesReynolds) * in.muG / (in.rhoG * in.dp);
  }

  // x = Delta* Fr_p^(2/3) = Delta / (v_t^2 d_p^2 / g)^(1/3).
  double scaledFilterSize(const DragInput& in) const noexcept {
    const double vt = terminalVelocity(in);
    return filterSize_ / std::cbrt(vt * vt * in.dp * in.dp / gravity_);
  }

  // H; `clamped` tells whether h(phi) < 0 was raised to 0 (H = 0).
  double correction(const DragInput& in, bool& clamped) const noexcept {
    const double phi = 1.0 - in.alphaG;
    const double h = largeFilterCorrection(phi);
    clamped = h < 0.0;
    if (clamped) return 0.0;
    const double x = scaledFilterSize(in);
    return h * x / (halfCorrectionFilterSize(phi) + x);
  }

  // K = (1 - H) K_BVK [kg/(m^3 s)]; forEachParcel counts `clamped`.
  double coefficient(const DragInput& in, bool& clamped) const noexcept {
    return (1.0 - correction(in, clamped)) * microscopic_.coefficient(in);
  }
  double coefficient(const DragInput& in) const noexcept {
    bool clamped = false;
    return coefficient(in, clamped);
  }

 private:
  BeetstraDrag microscopic_;
  double filterSize_;
  double gravity_;
  double particleDensity_;
};

}  // namespace parcelflow::coupling
