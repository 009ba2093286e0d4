#!/usr/bin/python3
"""Plots of a fluidized_column run: bed pressure drop against the bed weight per area, and the bed's
mean height, over time. Usage: plot.py [OUTPUT_FOLDER] (default: output next to this file)."""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

folder = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "output")
rows = list(csv.DictReader(open(os.path.join(folder, "monitors.csv"))))
t = [float(r["time"]) for r in rows]
dp = [float(r["bed_pressure_drop"]) for r in rows]
weight = [float(r["bed_weight_per_area"]) for r in rows]
height = [1000 * float(r["mean_z_type1"]) for r in rows]

fig, (a, b) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
a.plot(t, dp, lw=0.8, label="pressure drop between the planes")
a.plot(t, weight, lw=1.5, label="buoyant weight of the parcels above the lower plane / area")
a.set_ylabel("Pa")
a.legend(loc="lower right", fontsize=8)
b.plot(t, height, lw=1.0)
b.set_ylabel("mean parcel height [mm]")
b.set_xlabel("time [s]")
fig.suptitle("fluidized_column: 1 mm glass beads, U = 1.0 m/s")
fig.tight_layout()
path = os.path.join(folder, "fluidized_column.png")
fig.savefig(path, dpi=120)
half = [i for i, x in enumerate(t) if x >= t[-1] / 2]
mean_dp = sum(dp[i] for i in half) / len(half)
mean_w = sum(weight[i] for i in half) / len(half)
print(f"second half of the run: mean pressure drop {mean_dp:.1f} Pa, weight per area {mean_w:.1f} Pa "
      f"(ratio {mean_dp / mean_w:.3f})")
print(f"plot written: {path}")
