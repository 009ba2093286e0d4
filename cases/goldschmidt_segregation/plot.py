#!/usr/bin/python3
"""Plots of a goldschmidt_segregation run: the report every bed gets (cases/report/README.md: bed pressure drop
against the bed weight, the mean height of each size class, the measure Goldschmidt used, solids-fraction
snapshots on the mid-depth plane, the voids on the depth average, the mesoscale motion), drawn into the run
folder over the last half of the run (or the last 10 s if longer), and what is special to this bed: the
segregation (h_small - h_large) / h_mean with each class's height fluctuation, the last second's snapshots one
after the other (a bubble can be followed from the plate to the surface) and, for a run of at least 4 s, the
segregation and voids in 2 s windows.
Usage: plot.py [OUTPUT_FOLDER] (default: output next to this file)."""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "report"))
import figures  # noqa: E402
import report  # noqa: E402
import run_output  # noqa: E402

folder = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "output")
try:
    end = run_output.read_monitors(folder)["time"][-1]
except run_output.NotARun as e:
    print(f"plot.py: {e}", file=sys.stderr)
    sys.exit(2)
result = report.draw(folder, out=folder, start=max(end - 10.0, end / 2),
                     title="goldschmidt_segregation: 1.5 / 2.5 mm glass, 50/50 by mass, U = 1.1 m/s",
                     labels={"mean_z_type1": "1.5 mm beads", "mean_z_type2": "2.5 mm beads"})
monitors = result["monitors"]
t, small, large = monitors["time"], monitors["mean_z_type1"], monitors["mean_z_type2"]
dp, weight = monitors["bed_pressure_drop"], monitors["bed_weight_per_area"]
window = t >= result["start"] - 1e-12
h_small, h_large = small[window].mean(), large[window].mean()


def rms_mm(h):
    """Fluctuation of a class's mean height over the window: rms about its mean and about its linear trend
    (the second excludes a segregation still drifting) [mm]."""
    about_trend = h[window] - np.polyval(np.polyfit(t[window], h[window], 1), t[window])
    return 1000 * h[window].std(), 1000 * about_trend.std()


print(f"segregation (h_small - h_large)/h_mean = {(h_small - h_large) / (0.5 * (h_small + h_large)):+.3f}")
for name, h in (("small", small), ("large", large)):
    print("rms of the %s class's mean height: %.2f mm about its mean, %.2f mm about its linear trend"
          % ((name,) + rms_mm(h)))

last = [(time, path) for time, path in result["snapshots"] if time > t[-1] - 1.0 + 1e-9][-10:]
if last:
    png = figures.solids_planes(result["mesh"], [(time, run_output.read_field(path, "gas_fraction"))
                                                 for time, path in last], folder,
                                name="goldschmidt_solids_fraction_last_second.png",
                                title="solids fraction on the mid-depth plane, the last second")
    print(f"written: {png}")

# A longer run in 2 s windows: how the segregation develops and whether the voids change with it.
if t[-1] >= 4.0:
    print("window   small [mm]  large [mm]  segregation  dp/(W/A)  rms dp/(W/A)  layer share  bubbles/plane")
    for a in np.arange(0.0, t[-1] - 1.0, 2.0):
        w = (t >= a) & (t < a + 2.0)
        hs, hl, ratio = small[w].mean(), large[w].mean(), dp[w] / weight[w]
        rows = [r for r in result["void_rows"] if a <= r["time"] < a + 2.0]
        v = report.void_summary(rows) if rows else {"layer_share": np.nan, "bubbles_per_plane": np.nan}
        print(f"{a:4.0f}-{a + 2:<3.0f} {1000 * hs:10.1f}  {1000 * hl:10.1f}  {(hs - hl) / (0.5 * (hs + hl)):11.3f}  "
              f"{ratio.mean():8.3f}  {ratio.std():12.3f}  {v['layer_share']:11.2f}  {v['bubbles_per_plane']:13.2f}")
