#!/usr/bin/env python3
"""Smoke test of cases/openfoam_dpmfoam_goldschmidt (issue 5): the case as shipped for 1 ms (50 gas steps).

Checks that the bed is the tutorial's: 24,750 beads whose first monitored mean height is that of the
tutorial's lattice (kinematicCloudPositions: 5 x 50 x 99 points, 3 mm apart from 1.5 mm, so a mean
height of 0.1485 m), that no bead is lost, and that the beads' mean height after 1 ms lies between
free fall and rest: z(0) - g t^2/2 < z(t) < z(0), since the gas (blowing upwards from t = 0) slows their
fall but cannot lift the lattice (its drag at the start, Ergun at a_g = 0.70, is about 0.36 of the weight).

usage: dpmfoam_goldschmidt_smoke.py PARCELFLOW MPIEXEC...
"""
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, fail, run_case  # noqa: E402

END, G, BEADS = 1.0e-3, 9.81, 24750
LATTICE_MEAN_Z = 0.0015 + 0.003 * (99 - 1) / 2


def edit(case):
    case["time"]["end"] = END
    case["output"]["monitor_interval"] = END / 5


def main():
    parcelflow, launcher = sys.argv[1], sys.argv[2:]
    out = run_case(parcelflow, launcher, os.path.join(CASES, "openfoam_dpmfoam_goldschmidt"), edit)
    rows = list(csv.DictReader(open(os.path.join(out, "monitors.csv"))))
    log = open(os.path.join(out, "log.liggghts")).read()
    if f"Created {BEADS} atoms" not in log:
        fail(f"LIGGGHTS did not create {BEADS} beads on the lattice")
    if any(float(r["lost_parcels"]) != 0 for r in rows):
        fail("beads were lost")
    z0, z_end, t_end = float(rows[0]["mean_z_type1"]), float(rows[-1]["mean_z_type1"]), float(rows[-1]["time"])
    print(f"[measured] mean height {z0:.9f} m after the first step (lattice {LATTICE_MEAN_Z} m), "
          f"{z_end:.6f} m at {t_end} s (free fall {LATTICE_MEAN_Z - 0.5 * G * t_end**2:.6f} m)")
    if abs(z0 - LATTICE_MEAN_Z) > 1e-7:
        fail("the beads do not start on the tutorial's lattice")
    if abs(t_end - END) > 1e-12 or not LATTICE_MEAN_Z - 0.5 * G * END**2 < z_end < LATTICE_MEAN_Z:
        fail("the beads' mean height is not between free fall and rest")
    print("PASS")


if __name__ == "__main__":
    main()
