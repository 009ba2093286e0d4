#!/usr/bin/python3
"""Plots of a goldschmidt_segregation run: the mean height of each size class against time (the measure
Goldschmidt used), the bed pressure drop against the bed weight, and solids-fraction snapshots from the
HDF5 fields (six times over the run, and the last second's snapshots one after the other). Prints the
segregation summary, the void measure and the mesoscale motion (mesoscale.py) over the last half of the run
(or the last 10 s if longer) and, for a run of at least 4 s, the segregation and voids in 2 s windows.
Usage: plot.py [OUTPUT_FOLDER] (default: output next to this file)."""
import csv
import os
import sys

import h5py
import matplotlib
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesoscale  # noqa: E402
import void_shape  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

folder = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "output")
rows = list(csv.DictReader(open(os.path.join(folder, "monitors.csv"))))
t = np.array([float(r["time"]) for r in rows])
small = np.array([float(r["mean_z_type1"]) for r in rows])
large = np.array([float(r["mean_z_type2"]) for r in rows])
dp = np.array([float(r["bed_pressure_drop"]) for r in rows])
weight = np.array([float(r["bed_weight_per_area"]) for r in rows])

fig, (a, b) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
a.plot(t, 1000 * small, lw=0.8, label="1.5 mm beads")
a.plot(t, 1000 * large, lw=0.8, label="2.5 mm beads")
a.set_ylabel("mean height of the class [mm]")
a.legend(fontsize=8)
b.plot(t, dp, lw=0.6, label="bed pressure drop (monitors.bed_pressure_drop)")
b.plot(t, weight, lw=1.2, label="buoyant bed weight / area")
b.set_ylabel("Pa")
b.set_xlabel("time [s]")
b.legend(fontsize=8)
fig.suptitle("goldschmidt_segregation: 1.5 / 2.5 mm glass, 50/50 by mass, U = 1.1 m/s")
fig.tight_layout()
heights_png = os.path.join(folder, "goldschmidt_heights.png")
fig.savefig(heights_png, dpi=120)


def plot_snapshots(picked, png, title):
    """Solids fraction on the mid plane (the middle of the 5 cells across the depth) of the field files
    picked [(path, time), ...]."""
    with h5py.File(os.path.join(folder, "fields_mesh.h5"), "r") as f:
        centre = np.asarray(f["points"]).reshape(-1, 8, 3).mean(axis=1)  # output order
    spacing = [np.diff(np.unique(np.round(centre[:, d], 9)))[0] for d in range(3)]
    index = [np.rint((centre[:, d] - centre[:, d].min()) / spacing[d]).astype(int) for d in range(3)]
    shape = [i.max() + 1 for i in index]
    mid = index[1] == shape[1] // 2
    fig, axes = plt.subplots(1, len(picked), figsize=(2.0 * len(picked), 6), squeeze=False)
    for ax, (path, time) in zip(axes[0], picked):
        with h5py.File(path, "r") as f:
            solids_out = 1.0 - np.asarray(f["gas_fraction"])
        plane = np.full((shape[2], shape[0]), np.nan)
        plane[index[2][mid], index[0][mid]] = solids_out[mid]
        top = centre[:, 2].max() + 0.5 * spacing[2]
        ax.imshow(plane, origin="lower", extent=[0, shape[0] * spacing[0], 0, top], vmin=0, vmax=0.65,
                  cmap="viridis", aspect="auto")
        ax.set_ylim(0, 0.5 * top)
        ax.set_title(f"t = {time:.2f} s", fontsize=8)
        ax.set_xticks([])
    axes[0][0].set_ylabel("z [m]")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print(f"plot written: {png}")


# Six times spread over the run, and the last second's snapshots one after the other (up to 10), in which a
# bubble can be followed from the plate to the surface.
snapshots = void_shape.read_snapshots(folder)  # [(path, time, depth-averaged gas fraction), ...]
if snapshots:
    spread = [snapshots[int(i)][:2] for i in np.linspace(0, len(snapshots) - 1, min(6, len(snapshots)))]
    plot_snapshots(spread, os.path.join(folder, "goldschmidt_solids_fraction.png"),
                   "solids fraction on the mid plane (0 to 0.65)")
    last = [(path, time) for path, time, _ in snapshots if time > t[-1] - 1.0 + 1e-9][-10:]
    if last:
        plot_snapshots(last, os.path.join(folder, "goldschmidt_solids_fraction_last_second.png"),
                       "solids fraction on the mid plane, the last second (0 to 0.65)")


def void_measure(start, end=float("inf")):
    """void_shape's measure over the snapshots at times in [start, end)."""
    return void_shape.run_measure([a for _, time, a in snapshots if start <= time < end])


window = t >= max(t[-1] - 10.0, t[-1] / 2)
h_small, h_large = small[window].mean(), large[window].mean()
h_mean = 0.5 * (h_small + h_large)


def rms_mm(h):
    """Fluctuation of a class's mean height over the window: rms about its mean and about its linear trend
    (the second excludes a segregation still drifting) [mm]."""
    about_trend = h[window] - np.polyval(np.polyfit(t[window], h[window], 1), t[window])
    return 1000 * h[window].std(), 1000 * about_trend.std()


print(f"over {t[window][0]:.2f}-{t[-1]:.2f} s: mean height small {1000 * h_small:.2f} mm, large {1000 * h_large:.2f} mm; "
      f"segregation (h_small - h_large)/h_mean = {(h_small - h_large) / h_mean:+.3f}; dp/(W/A) = "
      f"{dp[window].mean() / weight[window].mean():.3f}")
for name, h in (("small", small), ("large", large)):
    print("rms of the %s class's mean height: %.2f mm about its mean, %.2f mm about its linear trend" % ((name,) + rms_mm(h)))
voids = void_measure(t[window][0])
print(f"voids over {voids['snapshots']} field snapshots of the same window (void_shape.py): a bed-wide gas layer in "
      f"{100 * voids['layer_share']:.0f} %, {voids['bubbles_per_snapshot']:.2f} bubbles per snapshot, mean bubble width "
      f"{1000 * voids['mean_bubble_width']:.1f} mm, lateral spread of the gas fraction {voids['lateral_spread']:.3f}")
motion = mesoscale.run_measure(folder, t[window][0], t[-1], 3)
if motion:
    print(f"mesoscale motion over the same window (mesoscale.py, boxes of 3 x 3 cells): box-velocity variance of the "
          f"solids x {1e4 * motion['solids_var_x']:.1f}, z {1e4 * motion['solids_var_z']:.1f} cm2/s2, of the gas "
          f"x {1e4 * motion['gas_var_x']:.0f}, z {1e4 * motion['gas_var_z']:.0f} cm2/s2")
print(f"plot written: {heights_png}")

# A longer run in 2 s windows: how the segregation develops and whether the voids change with it.
if t[-1] >= 4.0:
    print("window   small [mm]  large [mm]  segregation  dp/(W/A)  rms dp/(W/A)  layer share  bubbles/snapshot")
    for a in np.arange(0.0, t[-1] - 1.0, 2.0):
        w = (t >= a) & (t < a + 2.0)
        hs, hl, ratio = small[w].mean(), large[w].mean(), dp[w] / weight[w]
        v = void_measure(a, a + 2.0)
        print(f"{a:4.0f}-{a + 2:<3.0f} {1000 * hs:10.1f}  {1000 * hl:10.1f}  {(hs - hl) / (0.5 * (hs + hl)):11.3f}  "
              f"{ratio.mean():8.3f}  {ratio.std():12.3f}  {v['layer_share']:11.2f}  {v['bubbles_per_snapshot']:16.2f}")
