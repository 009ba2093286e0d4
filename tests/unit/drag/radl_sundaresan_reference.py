#!/usr/bin/python3
"""Reference values for RadlSundaresanFilteredBVK (tests/unit/drag/filtered_drag_test.cpp), computed
independently of the C++ code: the correlations typed in again from their sources, the terminal
velocity by bisection on the force balance (the C++ code uses Newton on ln Re), the fits evaluated with
numpy.polyval.

  filtered K = (1 - H) K_BVK,  H = max(h(phi), 0) x / (a(phi) + x),
  x = Delta* Fr_p^(2/3),  Delta* = Delta g / v_t^2,  Fr_p = v_t^2 / (g d_p),
  v_t: terminal velocity of one particle under BVK at phi = 0.

h and a: the piecewise cubic fits of Radl & Sundaresan (2014) as given in CFDEMcoupling-PFM's
BeetstraDrag.C (the paper's text was not available). Run: /usr/bin/python3 radl_sundaresan_reference.py
"""
import math

import numpy as np

RHO_G, MU_G, RHO_P, G = 1.2, 1.8e-5, 1500.0, 9.81

# (upper phi of the segment, phi the cubic is centred on, [c0, c1, c2, c3])
H_FIT = [(0.03, 0.0, [0.0, 7.97, 0.0, 0.0]),
         (0.08, 0.03, [0.239, 4.64, -4.41, 253.63]),
         (0.12, 0.08, [0.492, 6.10, 33.63, -789.6]),
         (0.18, 0.12, [0.739, 5.01, -61.1, 310.8]),
         (0.34, 0.18, [0.887, 1.03, -5.17, 5.99]),
         (0.48, 0.34, [0.943, -0.17, -2.29, -9.12]),
         (0.55, 0.48, [0.85, -1.35, -6.13, -132.6]),
         (math.inf, 0.55, [0.68, -2.34, -225.2, 0.0])]
A_FIT = [(0.016, 0.0, [21.51, 0.0, 0.0, 0.0]),
         (0.10, 0.0, [1.96, 29.4, 164.91, -1923.0]),
         (0.18, 0.10, [4.63, 4.68, -412.04, 2254.0]),
         (0.25, 0.18, [3.52, -17.99, 128.8, -603.0]),
         (0.40, 0.25, [2.68, -8.2, 2.18, 112.33]),
         (math.inf, 0.0, [1.79, 0.0, 0.0, 0.0])]


def piecewise(fit, phi):
    for upper, centre, c in fit:
        if phi < upper:
            return float(np.polyval(c[::-1], phi - centre))
    raise ValueError(phi)


def bvk_F(phi, Re):
    """Beetstra et al. (2007) normalised drag, as printed (negative powers of Re)."""
    eps = 1.0 - phi
    return (10 * phi / eps**2 + eps**2 * (1 + 1.5 * math.sqrt(phi))
            + 0.413 * Re / (24 * eps**2) * (1 / eps + 3 * eps * phi + 8.4 * Re**-0.343)
            / (1 + 10**(3 * phi) * Re**(-(1 + 4 * phi) / 2)))


def bvk_K(alphaG, slip, dp, dmean=None):
    """K = beta / a_s of particle dp: 18 mu eps F(phi, Re<d>) (eps + phi y) / dp^2, y = dp / <d>."""
    dm = dp if dmean is None else dmean
    phi = 1 - alphaG
    Re = alphaG * RHO_G * slip * dm / MU_G
    return 18 * MU_G * alphaG * bvk_F(phi, Re) * (alphaG + phi * dp / dm) / dp**2


def terminal_velocity(dp):
    """3 pi mu d v F(0, Re) = (rho_p - rho_g) g pi d^3 / 6, solved by bisection in v."""
    def excess(v):
        Re = RHO_G * v * dp / MU_G
        return 3 * math.pi * MU_G * dp * v * bvk_F(0.0, Re) - (RHO_P - RHO_G) * G * math.pi * dp**3 / 6
    lo, hi = 1e-12, (RHO_P - RHO_G) * G * dp**2 / (18 * MU_G)  # Stokes velocity is an upper bound
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if excess(mid) < 0 else (lo, mid)
    return 0.5 * (lo + hi)


def correction(phi, dp, delta):
    """(H, clamped, Delta*, x)"""
    vt = terminal_velocity(dp)
    delta_star = delta * G / vt**2
    x = delta_star * (vt**2 / (G * dp))**(2.0 / 3.0)
    h = piecewise(H_FIT, phi)
    return max(h, 0.0) * x / (piecewise(A_FIT, phi) + x), h < 0, delta_star, x


def main():
    print("// terminal velocities [m/s]")
    for dp in (10e-6, 60e-6, 96e-6, 170e-6, 290e-6, 1e-3):
        vt = terminal_velocity(dp)
        print("{%.6g, %.17g},  // Re_t = %.6g" % (dp, vt, RHO_G * vt * dp / MU_G))
    print("// h(phi), a(phi)")
    for phi in (0.0, 0.01, 0.016, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.55, 0.6, 0.65):
        print("{%.3f, %.17g, %.17g}," % (phi, piecewise(H_FIT, phi), piecewise(A_FIT, phi)))
    print("// alphaG, slip, dp, dMean, Delta, K_filtered, H   (Delta*, x, Re)")
    rows = [(dp, None, delta, phi, Re) for dp in (60e-6, 170e-6) for delta in (1e-4, 0.045, 0.075)
            for phi in (0.01, 0.13, 0.3, 0.45, 0.62) for Re in (0.1, 100.0)]
    rows += [(60e-6, 96e-6, 0.045, 0.3, 5.0), (170e-6, 96e-6, 0.075, 0.45, 20.0)]  # polydisperse BVK part
    for dp, dmean, delta, phi, Re in rows:
        a = round(1 - phi, 2)  # the test's input is a_g (printed with 2 digits) ...
        phi = 1 - a            # ... and the law takes phi = 1 - a_g (0.09999999999999998 for a_g = 0.9)
        slip = Re * MU_G / (a * RHO_G * (dmean or dp))
        H, clamped, ds, x = correction(phi, dp, delta)
        K = (1 - H) * bvk_K(a, slip, dp, dmean)
        print("{%.2f, %.17g, %.6g, %.6g, %.6g, %.17g, %.17g},  // Delta* %.5g, x %.5g, Re %g%s"
              % (a, slip, dp, dmean or 0.0, delta, K, H, ds, x, Re, ", h < 0: clamped" if clamped else ""))
    print("# FCC: filtered / unfiltered drag (1 - H)")
    for delta in (0.075, 0.045):
        for dp in (60e-6, 96e-6, 170e-6):
            print("Delta %.3f m  dp %3.0f um  v_t %.4f m/s  Delta* %.4g  x %.4g :" % (
                delta, dp * 1e6, terminal_velocity(dp), correction(0.1, dp, delta)[2], correction(0.1, dp, delta)[3]),
                "  ".join("phi %.1f: %.4f" % (phi, 1 - correction(phi, dp, delta)[0]) for phi in (0.1, 0.3, 0.5)))


if __name__ == "__main__":
    main()
