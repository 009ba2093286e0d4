#!/usr/bin/env python3
"""Smoke test of cases/goldschmidt_segregation (issue 5): the case as shipped, cut to a 0.05 m wide slice
(16 x 5 x 94 cells, 11,230 beads: a third of the bed, the same 0.075 m static height) and 0.1 s of
coupled time, so that it fits in CI.

Checks: no parcel is lost; monitors.csv has a row after the first step and then every monitor interval,
with finite mean heights of both classes; fields.xdmf lists snapshots whose HDF5 files open and hold a
gas fraction in (0, 1] for all 7,520 cells; and the bed pressure drop balances the bed's weight and
momentum. 0.1 s is the start-up (the gas lifts the packed bed as a plug, which then slows down), so the
pressure drop is not yet its time average; the check is the impulse balance of the bed,
    integral of (dp - rho_g g H - W/A + F_walls/A) dt = (M/A) (v(T) - v(0)),
dp the pressure drop from the plate to H = 0.29 m (which also holds the gas's own weight), W the buoyant
weight of all beads, v = d<z>/dt of their mass-weighted mean height, F_walls the vertical contact force of
all walls on the beads (the plate; friction in the 15 mm slot), which the test has LIGGGHTS store and
print every gas step,
to 3 % of (W/A) T (the fluidized time average is tests 4 and 7 of fluidization.py).

usage: goldschmidt_smoke.py PARCELFLOW MPIEXEC...
"""
import csv
import math
import os
import re
import sys
import xml.etree.ElementTree as ElementTree

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, fail, run_case  # noqa: E402

CELLS = 16 * 5 * 94
GAS_STEP, DEM_STEP, MONITOR_INTERVAL, END, G = 5e-4, 5e-4 / 12, 0.0025, 0.1, 9.81
WIDTH, DEPTH, RHO_G, MONITORED_HEIGHT = 0.05, 0.015, 1.2, 0.29


def edit(case):
    case["liggghts"]["variables"].update({"nbeads": "11230", "width": str(WIDTH)})
    case["mesh"]["lengths"][0] = WIDTH
    case["mesh"]["cells"][0] = 16
    case["time"]["end"] = END
    case["output"]["fields_interval"] = 0.05
    case["output"]["monitor_interval"] = MONITOR_INTERVAL
    case["monitors"]["bed_pressure_drop"] = [0.0, MONITORED_HEIGHT]


WALL_FORCE_THERMO = """
variable wall_fz atom f_force_wx0[3]+f_force_wx1[3]+f_force_wy0[3]+f_force_wy1[3]+f_force_wz0[3]+f_force_wz1[3]
compute  walls all reduce sum v_wall_fz
thermo_style custom step c_walls
thermo_modify format float %.10g
thermo 12
"""


def store_wall_forces(script):
    """The case's script with every wall storing its force on the beads, printed every gas step."""
    text = open(script).read()
    # inside the quotes of a wall that an `if ... then "..." &` line defines (the side walls)
    wall = re.compile(r'^(.* wall/gran [^"]*?)("?\s*&?\s*)$')
    lines = [wall.sub(r"\1 store_force yes\2", line) for line in text.splitlines()]
    open(script, "w").write("\n".join(lines) + WALL_FORCE_THERMO)


def wall_impulse(log, dem_step, gas_start_step):
    """Integral over the coupled time of the walls' vertical force on the beads [N s]."""
    force = {}
    for line in open(log):
        parts = line.split()
        if len(parts) == 2 and parts[0].isdigit() and int(parts[0]) >= gas_start_step:
            force[int(parts[0])] = float(parts[1])
    steps = sorted(force)
    return sum(0.5 * (force[a] + force[b]) * (b - a) * dem_step for a, b in zip(steps, steps[1:]))


def main():
    parcelflow, launcher = sys.argv[1], sys.argv[2:]
    out = run_case(parcelflow, launcher, os.path.join(CASES, "goldschmidt_segregation"), edit,
                   prepare=lambda case: store_wall_forces(os.path.join(case, "goldschmidt.in")))

    rows = list(csv.DictReader(open(os.path.join(out, "monitors.csv"))))
    # A row after the first gas step, then one every monitor interval up to the end.
    times = [float(r["time"]) for r in rows]
    expected = [GAS_STEP] + [MONITOR_INTERVAL * k for k in range(1, round(END / MONITOR_INTERVAL) + 1)]
    if len(times) != len(expected) or max(abs(a - b) for a, b in zip(times, expected)) > 1e-9:
        fail(f"monitor rows at {times}, expected {expected}")
    if any(float(r["lost_parcels"]) != 0 for r in rows):
        fail("parcels were lost")
    for r in rows:
        for column in ("mean_z_type1", "mean_z_type2"):
            if not math.isfinite(float(r[column])):
                fail(f"{column} is not finite at t = {r['time']}")

    # The two classes have equal mass (50/50), so the bed's mean height is the mean of the two.
    height = [0.5 * (float(r["mean_z_type1"]) + float(r["mean_z_type2"])) for r in rows]
    gas_head = RHO_G * G * MONITORED_HEIGHT
    excess = [float(r["bed_pressure_drop"]) - gas_head - float(r["bed_weight_per_area"]) for r in rows]
    impulse = sum(0.5 * (excess[i] + excess[i + 1]) * (times[i + 1] - times[i]) for i in range(len(rows) - 1))
    # d<z>/dt at both ends from the quadratic through the three end rows (second order).
    velocity = (np.polyval(np.polyder(np.polyfit(times[-3:], height[-3:], 2)), times[-1]) -
                np.polyval(np.polyder(np.polyfit(times[:3], height[:3], 2)), times[0]))
    weight = sum(float(r["bed_weight_per_area"]) for r in rows) / len(rows)
    momentum = weight / G * velocity
    # The settled bed's last DEM step before the gas: 1 + settle_steps + 1000 (see goldschmidt.in).
    walls = wall_impulse(os.path.join(out, "log.liggghts"), DEM_STEP, 1 + 9000 + 1000) / (WIDTH * DEPTH)
    scale = weight * (times[-1] - times[0])
    balance = impulse + walls - momentum
    print(f"[measured] impulses per area: (dp - W/A) {impulse:.3f} Pa s, walls {walls:.3f} Pa s; bed momentum change "
          f"(M/A) dv {momentum:.3f} Pa s; imbalance {100 * balance / scale:+.2f} % of (W/A) T (allowed 3 %); "
          f"dp/(W/A) at the end {float(rows[-1]['bed_pressure_drop']) / float(rows[-1]['bed_weight_per_area']):.3f}")
    if abs(balance) > 0.03 * scale:
        fail("the bed pressure drop does not balance the bed's weight and momentum")

    xdmf = ElementTree.parse(os.path.join(out, "fields.xdmf"))
    files = sorted({item.text.strip().split(":")[0] for item in xdmf.iter("DataItem")
                    if item.text and ".h5:" in item.text and "fields_0" in item.text})
    if len(files) < 2:
        fail(f"fields.xdmf lists {len(files)} snapshot files, expected at least 2")
    for name in files:
        with h5py.File(os.path.join(out, name), "r") as f:
            alpha = np.asarray(f["gas_fraction"])
            if alpha.shape != (CELLS,) or not (alpha > 0).all() or not (alpha <= 1).all():
                fail(f"{name}: gas_fraction has shape {alpha.shape}, range {alpha.min()}..{alpha.max()}")
    print(f"[measured] {len(files)} field snapshots readable, {len(rows)} monitor rows")
    print("PASS")


if __name__ == "__main__":
    main()
