#!/usr/bin/python3
"""The FCC size distribution of cases/psri_fcc_bubbling_bed (an ASSUMPTION: the experiment's own tables are not
public) and the numbers derived from it: d50, Sauter mean d32, the Wen-Yu minimum fluidization velocity and the
terminal velocities of the smallest and largest class.

Shape: a log-normal mass distribution with geometric standard deviation sigma_g = 1.5 (typical of equilibrium
FCC) whose median is chosen so that exactly 3 % of the mass lies below 45 um (the paper's "3 % fines"),
truncated to 10-290 um (the paper's range) and binned into 16 classes (bin edges half-way between the class
sizes; the edge between the 40 and 50 um classes is 45 um). Every class is given at least 0.2 % of the mass
(so that the 10 um and 290 um classes hold about 1,000 of the full case's 520,000 parcels instead of none);
the classes below 45 um are then scaled to 3.0 % together and the others to 97.0 %.

Prints the table, the `distribution` arguments of `fix parcel`, and checks that fcc_bed.in carries the same.
Gas: air at 1.2 kg/m3, 1.8e-5 Pa s; particles 1500 kg/m3; g = 9.81 m/s2.
Usage: distribution.py (no arguments)."""
import math
import os
import re
import sys

RHO_G, MU, RHO_P, G = 1.2, 1.8e-5, 1500.0, 9.81
SIGMA_G, FINES_EDGE, FINES, FLOOR = 1.5, 45e-6, 0.03, 0.002
CLASSES_UM = [10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 120, 140, 170, 210, 250, 290]


def phi(x):
    return 0.5 * (1.0 + math.erf(x / math.sqrt(2.0)))


def table():
    """Class diameters [m] and mass fractions."""
    s = math.log(SIGMA_G)
    d_median = FINES_EDGE * math.exp(-s * _inverse_phi(FINES))  # P(d < 45 um) = 3 % before truncation
    d = [c * 1e-6 for c in CLASSES_UM]
    edges = [d[0]] + [0.5 * (a + b) for a, b in zip(d, d[1:])] + [d[-1]]
    cdf = [phi(math.log(e / d_median) / s) for e in edges]
    f = [max(FLOOR, cdf[k + 1] - cdf[k]) for k in range(len(d))]
    fine = [k for k in range(len(d)) if d[k] < FINES_EDGE]
    fine_sum = sum(f[k] for k in fine)
    coarse_sum = sum(f[k] for k in range(len(d)) if k not in fine)
    f = [f[k] * (FINES / fine_sum if k in fine else (1.0 - FINES) / coarse_sum) for k in range(len(d))]
    f = [round(x, 5) for x in f]
    f[CLASSES_UM.index(80)] += round(1.0 - sum(f), 5)  # the rounding remainder to the largest class
    return d, f, d_median, edges


def _inverse_phi(p):
    lo, hi = -10.0, 10.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if phi(mid) < p else (lo, mid)
    return 0.5 * (lo + hi)


def archimedes(d):
    return RHO_G * (RHO_P - RHO_G) * G * d ** 3 / MU ** 2


def u_mf_wen_yu(d):
    """Wen & Yu (1966): Re_mf = sqrt(33.7^2 + 0.0408 Ar) - 33.7."""
    return (math.sqrt(33.7 ** 2 + 0.0408 * archimedes(d)) - 33.7) * MU / (RHO_G * d)


def terminal_velocity(d):
    """Single particle in still air with the drag of the project's laws (DESIGN section 4):
    C_D = 24/Re (1 + 0.15 Re^0.687) for Re < 1000, else 0.44; solved by bisection."""
    def excess(u):  # drag - buoyant weight
        re = RHO_G * u * d / MU
        cd = 24.0 / re * (1 + 0.15 * re ** 0.687) if re < 1000 else 0.44
        return cd * 0.5 * RHO_G * u * u * math.pi * d * d / 4 - (RHO_P - RHO_G) * G * math.pi * d ** 3 / 6
    lo, hi = 1e-12, 100.0
    for _ in range(200):
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if excess(mid) < 0 else (lo, mid)
    return math.sqrt(lo * hi)


def mass_median(d, f, edges):
    """d50 by linear interpolation of the cumulative mass over the bin edges."""
    cum = 0.0
    for k in range(len(d)):
        if cum + f[k] >= 0.5:
            return edges[k] + (0.5 - cum) / f[k] * (edges[k + 1] - edges[k])
        cum += f[k]
    return edges[-1]


def fix_arguments(d, f):
    return " ".join(f"{x * 1e6:g}e-6 {y:g}" for x, y in zip(d, f))


def main():
    d, f, d_median, edges = table()
    print(f"assumed shape: log-normal by mass, sigma_g = {SIGMA_G}, median {d_median * 1e6:.1f} um "
          f"(3 % below 45 um), truncated to 10-290 um, every class >= {100 * FLOOR:.1f} %")
    print("class [um]  bin [um]        mass fraction  U_mf [m/s]  u_t [m/s]")
    for k in range(len(d)):
        print(f"{d[k] * 1e6:8.0f}    {edges[k] * 1e6:5.0f}-{edges[k + 1] * 1e6:<5.0f}    {f[k]:10.5f}   "
              f"{u_mf_wen_yu(d[k]):10.3e}  {terminal_velocity(d[k]):9.3e}")
    fines = sum(fk for dk, fk in zip(d, f) if dk < FINES_EDGE)
    d32 = 1.0 / sum(fk / dk for dk, fk in zip(d, f))
    d50 = mass_median(d, f, edges)
    print(f"sum of fractions {sum(f):.6f}; below 45 um: {100 * fines:.2f} % by mass")
    print(f"d50 (mass median) = {d50 * 1e6:.1f} um; Sauter mean d32 = {d32 * 1e6:.1f} um")
    print(f"U_mf (Wen-Yu at d32) = {u_mf_wen_yu(d32) * 1000:.2f} mm/s (Ar = {archimedes(d32):.2f}); "
          f"U / U_mf at 0.6 m/s = {0.6 / u_mf_wen_yu(d32):.0f}")
    print(f"U_mf (Wen-Yu at d50) = {u_mf_wen_yu(d50) * 1000:.2f} mm/s")
    for dk in (d[0], d[-1]):
        u_t = terminal_velocity(dk)
        print(f"terminal velocity of the {dk * 1e6:.0f} um class: {u_t:.4g} m/s "
              f"(Re = {RHO_G * u_t * dk / MU:.3g})")
    carried = sum(fk for dk, fk in zip(d, f) if terminal_velocity(dk) < 0.6)
    print(f"mass with u_t < 0.6 m/s (carried by the superficial velocity in a particle-free freeboard): "
          f"{100 * carried:.1f} %")
    arguments = fix_arguments(d, f)
    print("fix parcel distribution: " + arguments)

    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fcc_bed.in")
    text = open(script).read().replace("&\n", " ")
    found = re.search(r"distribution\s+((?:[0-9.e+-]+\s+[0-9.e+-]+\s+)+)", text)
    written = found.group(1).split() if found else []
    expected = arguments.split()
    same = len(written) == len(expected) and all(
        math.isclose(float(a), float(b), rel_tol=1e-9) for a, b in zip(written, expected))
    print("fcc_bed.in carries this table" if same else "fcc_bed.in carries ANOTHER table: " + " ".join(written))
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
