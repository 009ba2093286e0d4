#!/usr/bin/env python3
"""Fluidization checks of the coupled solver on cases/fluidized_column (issue 4, tests 4-7).

  pressure_drop U   the bed at superficial velocity U: the pressure drop across it, averaged over
                    0.3-1.0 s, must equal the bed's buoyant weight per area within 2 %.
  umf NP            minimum fluidization from a stepwise velocity ramp (independent runs from the same
                    settled bed, parcels of NP beads): the packed branch dp(U) = a U + b U^2 (Ergun's form)
                    is fitted to the points below 0.9 W/A; where it reaches W/A is U_mf, which must lie
                    within 10 % of the Wen-Yu correlation (0.538 m/s for 1 mm glass in air).
  coarse_vs_fine    U_mf and the fluidized pressure drop with np = 1 (9,168 beads) and np = 8 (1,146
                    parcels) must agree within 5 %.

The ramps run the column with periodic sides for the beads and free-slip side walls for the gas: a cut
from an unbounded bed, which is what the Wen-Yu correlation describes. With walls the 20 mm column is
only 10 parcels (np 8) wide, the packing next to the walls is loose (gas fraction 0.52 in the corner
columns) and the gas channels along them: U_mf came out 0.698 m/s (np 8, +30 %) and 0.593 m/s (np 1).

usage: fluidization.py PARCELFLOW MPIEXEC... -- CHECK [ARG]
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, run_case  # noqa: E402
from verify_coupled import MU, RHO_G, RHO_P, G  # noqa: E402

BEAD = 1.0e-3
COLUMN = os.path.join(CASES, "fluidized_column")
FLUIDIZED_U = 0.75
RAMP = [0.25, 0.3, 0.35, 0.4, 0.45, 0.6]


def bed_of(np_beads):
    """LIGGGHTS variables for the same 9,168-bead bed as parcels of np_beads beads."""
    n = 9168 // np_beads
    assert n * np_beads == 9168, np_beads
    radius = 0.5 * BEAD * np_beads ** (1.0 / 3.0)
    return {"np": str(np_beads), "radius": repr(radius), "nparcels": str(n), "skin": repr(0.4 * radius)}


def mean_pressure_ratio(parcelflow, launcher, np_beads, velocity, end, average_from, periodic_sides=False):
    def edit(case):
        case["liggghts"]["variables"].update(bed_of(np_beads), periodic_sides="1" if periodic_sides else "0")
        if periodic_sides:
            for side in ("xmin", "xmax", "ymin", "ymax"):
                case["boundaries"][side] = {"type": "wall", "slip": "free_slip"}
        case["boundaries"]["zmin"]["superficial_velocity"] = [0, 0, velocity]
        case["time"]["end"] = end
        case["output"]["monitor_interval"] = 0.005

    out = run_case(parcelflow, launcher, COLUMN, edit)
    rows = [r for r in csv.DictReader(open(os.path.join(out, "monitors.csv"))) if float(r["time"]) > average_from]
    if any(float(r["lost_parcels"]) != 0 for r in rows):
        sys.exit("FAIL: parcels were lost")
    dp = sum(float(r["bed_pressure_drop"]) for r in rows) / len(rows)
    weight = sum(float(r["bed_weight_per_area"]) for r in rows) / len(rows)
    return dp / weight


def wen_yu_umf(d):
    archimedes = RHO_G * (RHO_P - RHO_G) * G * d**3 / MU**2
    return (math.sqrt(33.7**2 + 0.0408 * archimedes) - 33.7) * MU / (RHO_G * d)


def ramp_umf(parcelflow, launcher, np_beads):
    """U_mf where the fitted packed branch a U + b U^2 reaches W/A; also the plateau points."""
    points = [(u, mean_pressure_ratio(parcelflow, launcher, np_beads, u, 0.5, 0.25, True)) for u in RAMP]
    for u, r in points:
        print(f"[measured] np {np_beads}: U = {u:.3f} m/s  dp/(W/A) = {r:.4f}")
    packed = [(u, r) for u, r in points if r < 0.9]
    if len(packed) < 2:
        sys.exit(f"FAIL: fewer than two packed-bed points below 0.9 W/A: {points}")
    # Least squares for r = a u + b u^2.
    s11 = sum(u**2 for u, _ in packed)
    s12 = sum(u**3 for u, _ in packed)
    s22 = sum(u**4 for u, _ in packed)
    t1 = sum(u * r for u, r in packed)
    t2 = sum(u * u * r for u, r in packed)
    det = s11 * s22 - s12 * s12
    a, b = (t1 * s22 - t2 * s12) / det, (s11 * t2 - s12 * t1) / det
    umf = (-a + math.sqrt(a * a + 4 * b)) / (2 * b) if abs(b) > 1e-12 else 1.0 / a
    print(f"[measured] np {np_beads}: packed branch dp/(W/A) = {a:.4f} U + {b:.4f} U^2, U_mf = {umf:.4f} m/s")
    return umf, points


def check_pressure_drop(parcelflow, launcher, velocity):
    ratio = mean_pressure_ratio(parcelflow, launcher, 8, velocity, 1.0, 0.3)
    print(f"[measured] U = {velocity} m/s: time-averaged dp/(W/A) = {ratio:.4f} (allowed 0.98-1.02)")
    if abs(ratio - 1.0) > 0.02:
        sys.exit("FAIL: fluidized-bed pressure drop differs from the bed weight by more than 2 %")


def check_umf(parcelflow, launcher, np_beads):
    umf, _ = ramp_umf(parcelflow, launcher, np_beads)
    reference = wen_yu_umf(BEAD)
    error = umf / reference - 1.0
    print(f"[measured] U_mf = {umf:.4f} m/s, Wen-Yu correlation {reference:.4f} m/s, error {100 * error:+.1f} % "
          "(allowed 10 %)")
    if abs(error) > 0.10:
        sys.exit("FAIL: minimum fluidization velocity differs from the Wen-Yu correlation by more than 10 %")


def check_coarse_vs_fine(parcelflow, launcher):
    results = {}
    for np_beads in (1, 8):
        umf, _ = ramp_umf(parcelflow, launcher, np_beads)
        dp = mean_pressure_ratio(parcelflow, launcher, np_beads, FLUIDIZED_U, 1.0, 0.3, True)
        print(f"[measured] np {np_beads}: U_mf = {umf:.4f} m/s, dp/(W/A) at {FLUIDIZED_U} m/s = {dp:.4f}")
        results[np_beads] = (umf, dp)
    umf_diff = results[8][0] / results[1][0] - 1.0
    dp_diff = results[8][1] / results[1][1] - 1.0
    print(f"[measured] np 8 against np 1: U_mf {100 * umf_diff:+.2f} %, pressure drop {100 * dp_diff:+.2f} % "
          "(allowed 5 %)")
    if abs(umf_diff) > 0.05 or abs(dp_diff) > 0.05:
        sys.exit("FAIL: coarse-grained and fine beds differ by more than 5 %")


def main():
    split = sys.argv.index("--")
    parcelflow, launcher = sys.argv[1], sys.argv[2:split]
    check, args = sys.argv[split + 1], sys.argv[split + 2:]
    if check == "pressure_drop":
        check_pressure_drop(parcelflow, launcher, float(args[0]))
    elif check == "umf":
        check_umf(parcelflow, launcher, int(args[0]))
    elif check == "coarse_vs_fine":
        check_coarse_vs_fine(parcelflow, launcher)
    else:
        sys.exit(f"unknown check '{check}' (allowed: pressure_drop, umf, coarse_vs_fine)")
    print("PASS")


if __name__ == "__main__":
    main()
