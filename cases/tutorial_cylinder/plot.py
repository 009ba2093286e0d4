#!/usr/bin/python3
"""Plots of a tutorial_cylinder run (any bed with bed_pressure_drop and mean_z_type1 monitors): the bed
pressure drop against the parcels' weight per area, and their mean height, over time; prints their ratio over
the second half of the run. Usage: plot.py OUTPUT_FOLDER"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

if len(sys.argv) == 2 and sys.argv[1] in ("-h", "--help"):
    print(__doc__)
    sys.exit(0)
if len(sys.argv) != 2:
    sys.exit(__doc__)
folder = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(folder, "monitors.csv"))))
t = [float(r["time"]) for r in rows]
dp = [float(r["bed_pressure_drop"]) for r in rows]
weight = [float(r["bed_weight_per_area"]) for r in rows]
height = [1000 * float(r["mean_z_type1"]) for r in rows]

fig, (a, b) = plt.subplots(2, 1, figsize=(7, 5), sharex=True)
a.plot(t, dp, lw=0.8, label="bed pressure drop")
a.plot(t, weight, lw=1.5, label="buoyant weight of the parcels / area")
a.set_ylabel("Pa")
a.legend(loc="lower right", fontsize=8)
b.plot(t, height, lw=1.0)
b.set_ylabel("mean parcel height [mm]")
b.set_xlabel("time [s]")
fig.tight_layout()
path = os.path.join(folder, "bed.png")
fig.savefig(path, dpi=120)
half = [i for i, x in enumerate(t) if x >= t[-1] / 2]
ratio = sum(dp[i] for i in half) / sum(weight[i] for i in half)
print(f"second half of the run: bed pressure drop / weight = {ratio:.3f}")
print(f"plot written: {path}")
