#!/usr/bin/python3
"""Plots of a psri_fcc_bubbling_bed run (any variant): the report every bed gets (cases/report/README.md), drawn
into the run folder: the bed pressure drop against the bed's buoyant weight per area, the parcels' mean height,
the solids fraction on the vertical mid plane at up to six snapshots (paper, Figure 4), the voids and, from
monitors.average, the time-averaged pressure and dp/(g dz) against height with the bed height (paper, Figure 8)
and the time-averaged solids fraction, gas speed and solids speed on the mid plane (paper, Figure 7); and what
is special to this bed:
- fcc_monitors.png: pressures on a few planes and the reinjection columns of monitors.csv (cumulative out / in
  and pending; the panel stays empty for a run without them);
- printed: the averaged solids speeds below and above the sparger and the gas speed in the exit tube, and the
  reinjection balance.
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
result = report.draw(folder, out=folder, title="psri_fcc_bubbling_bed")
monitors = result["monitors"]
t = monitors["time"]

# --- pressures on the planes and the reinjection --------------------------------------------------------
columns = ("reinjection_pending", "reinjected_out_total", "reinjected_in_total", "lost_parcels")
reinjection = np.column_stack([monitors[c] for c in columns]) if all(c in monitors for c in columns) else None
plane_keys = [k for k in monitors if k.startswith("p_z")]
fig, axes = figures.plt.subplots(2, 1, figsize=(8, 7), sharex=True)
for k in plane_keys[:: max(1, len(plane_keys) // 6)]:
    axes[0].plot(t, monitors[k] / 1000, lw=0.6, label=k[2:])
axes[0].set_ylabel("pressure [kPa]")
if plane_keys:
    axes[0].legend(fontsize=7, ncol=3)
if reinjection is not None:
    axes[1].plot(t, reinjection[:, 1], label="cumulative out")
    axes[1].plot(t, reinjection[:, 2], "--", label="cumulative in")
    axes[1].plot(t, reinjection[:, 0], label="pending")
    axes[1].legend(fontsize=8)
axes[1].set_xlabel("time [s]")
axes[1].set_ylabel("parcels")
fig.suptitle("psri_fcc_bubbling_bed: pressures on the planes and the reinjection")
fig.tight_layout()
print(f"written: {figures.save(fig, folder, 'fcc_monitors.png')}")
if reinjection is not None:
    pending, out, back, lost = reinjection[-1]
    print(f"reinjection: {out:.0f} parcels out, {back:.0f} in, {pending:.0f} pending at the end "
          f"(at most {reinjection[:, 0].max():.0f}); parcels lost {lost:.0f}")

# --- averaged speeds below / above the sparger and in the exit tube -------------------------------------
averaged = run_output.series(folder, "averages")
if averaged:
    mesh = run_output.Mesh(os.path.join(folder, "averages_mesh.h5"))
    path = averaged[-1][1]
    solids, solids_speed, gas_speed = (run_output.read_field(path, k) for k in
                                       ("mean_solids_fraction", "mean_solids_speed", "mean_gas_speed"))
    z = mesh.centres[:, 2]
    held = solids > 0.05
    print("time-averaged solids speed (cells with mean solids fraction > 0.05): " + ", ".join(
        f"{lo:.1f}-{hi:.1f} m: {solids_speed[(z >= lo) & (z < hi) & held].mean():.3f} m/s"
        for lo, hi in ((0.0, 0.25), (0.35, 1.0), (1.0, 2.0)) if ((z >= lo) & (z < hi) & held).any()))
    # The exit tube: the layers of cells narrower than half the widest layer (the column).
    per_layer = np.bincount(mesh.index[2])
    tube = per_layer[mesh.index[2]] < 0.5 * per_layer.max()
    if tube.any():
        print(f"time-averaged gas speed in the exit tube: {gas_speed[tube].mean():.2f} m/s "
              f"(largest {gas_speed[tube].max():.2f} m/s)")
