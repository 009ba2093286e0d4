#!/usr/bin/python3
"""Plots of a psri_fcc_bubbling_bed run (any variant), as the paper shows them:
- fcc_pressure_profile.png: the time-averaged bulk density dp/(g dz) against height and the time-averaged
  pressure on the planes (paper, Figure 8), from averages.csv, with the bed height of its header line;
- fcc_monitors.png: time series from monitors.csv: bed pressure drop against the bed's buoyant weight per
  area, the parcels' mean height, pressures on a few planes, and the reinjection columns of monitors.csv
  (cumulative out / in and pending; the panel stays empty for a run without them);
- fcc_solids_fraction.png: the solids fraction on the vertical mid plane of the column at up to six field
  snapshots (paper, Figure 4);
- fcc_averaged_fields.png: time-averaged solids fraction, gas speed and solids speed on the mid plane
  (paper, Figure 7), from averages.xdmf.
Prints the bed height, the averaged speeds below and above the sparger and in the exit tube, and the
reinjection balance. Usage: plot.py [OUTPUT_FOLDER] (default: output next to this file)."""
import csv
import glob
import os
import re
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

G = 9.81
folder = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "output")
written = []


def save(fig, name):
    path = os.path.join(folder, name)
    fig.savefig(path, dpi=120)
    plt.close(fig)
    written.append(path)


# --- Figure 8: averaged pressure and dp/(g dz) against height -------------------------------------------
averages_csv = os.path.join(folder, "averages.csv")
bed_height = float("nan")
if os.path.exists(averages_csv):
    lines = open(averages_csv).read().splitlines()
    found = re.search(r"time averages over ([0-9.e+-]+) s from t = ([0-9.e+-]+) s.*bed height (\S+) m", lines[0])
    span, start, bed_height = (float(found.group(k)) for k in (1, 2, 3)) if found else (np.nan, np.nan, np.nan)
    rows = list(csv.DictReader(lines[1:]))
    z = np.array([float(r["z"]) for r in rows if r["z"]])
    p = np.array([float(r["mean_pressure"]) for r in rows if r["z"]])
    mid = np.array([float(r["interval_mid_z"]) for r in rows if r.get("interval_mid_z")])
    rho_b = np.array([float(r["dp_over_g_dz"]) for r in rows if r.get("interval_mid_z")])
    fig, (a, b) = plt.subplots(1, 2, figsize=(9, 6), sharey=True)
    a.plot(rho_b, mid, "o-", ms=3)
    a.set_xlabel("dp / (g dz) [kg/m3]")
    a.set_ylabel("height z [m]")
    b.plot(p / 1000, z, "o-", ms=3)
    b.set_xlabel("time-averaged pressure [kPa]")
    for ax in (a, b):
        if np.isfinite(bed_height):
            ax.axhline(bed_height, color="gray", ls="--", lw=0.8, label=f"bed height {bed_height:.2f} m")
        ax.grid(alpha=0.3)
    a.legend(fontsize=8)
    fig.suptitle(f"psri_fcc_bubbling_bed: time averages over {span:g} s from t = {start:g} s (paper, Figure 8)")
    fig.tight_layout()
    save(fig, "fcc_pressure_profile.png")
    print(f"time averages over {span:g} s from t = {start:g} s: bed height {bed_height:.3f} m; "
          f"largest dp/(g dz) {rho_b.max():.0f} kg/m3 at z = {mid[rho_b.argmax()]:.2f} m")

# --- time series: monitors and reinjection --------------------------------------------------------------
monitors = list(csv.DictReader(open(os.path.join(folder, "monitors.csv"))))
t = np.array([float(r["time"]) for r in monitors])
columns = ("reinjection_pending", "reinjected_out_total", "reinjected_in_total", "lost_parcels")
reinjection = np.array([[float(r[c]) for c in columns] for r in monitors]) if columns[0] in monitors[0] else []
plane_keys = [k for k in monitors[0] if k.startswith("p_z")]
fig, axes = plt.subplots(4, 1, figsize=(8, 10), sharex=False)
axes[0].plot(t, [float(r["bed_pressure_drop"]) for r in monitors], lw=0.6, label="bed pressure drop")
axes[0].plot(t, [float(r["bed_weight_per_area"]) for r in monitors], lw=1.2, label="buoyant weight / area")
axes[0].set_ylabel("Pa")
axes[0].set_ylim(0, 2.0 * max(float(r["bed_weight_per_area"]) for r in monitors))
axes[0].legend(fontsize=8)
axes[1].plot(t, [float(r["mean_z_type1"]) for r in monitors], lw=0.8)
axes[1].set_ylabel("parcels' mean height [m]")
for k in plane_keys[:: max(1, len(plane_keys) // 6)]:
    axes[2].plot(t, [float(r[k]) / 1000 for r in monitors], lw=0.6, label=k[2:])
axes[2].set_ylabel("pressure [kPa]")
axes[2].set_xlabel("time [s]")
axes[2].legend(fontsize=7, ncol=3)
if len(reinjection):
    axes[3].plot(t, reinjection[:, 1], label="cumulative out")
    axes[3].plot(t, reinjection[:, 2], "--", label="cumulative in")
    axes[3].plot(t, reinjection[:, 0], label="pending")
    axes[3].legend(fontsize=8)
axes[3].set_xlabel("time [s]")
axes[3].set_ylabel("parcels")
fig.suptitle("psri_fcc_bubbling_bed: monitors")
fig.tight_layout()
save(fig, "fcc_monitors.png")
if len(reinjection):
    pending, out, back, lost = reinjection[-1]
    print(f"reinjection: {out:.0f} parcels out, {back:.0f} in, {pending:.0f} pending at the end "
          f"(at most {reinjection[:, 0].max():.0f}); parcels lost {lost:.0f}")


# --- mid-plane slices of the fields ---------------------------------------------------------------------
def mid_plane(mesh_file):
    with h5py.File(mesh_file, "r") as f:
        corners = np.asarray(f["points"]).reshape(-1, 8, 3)
    centre, lo, hi = corners.mean(axis=1), corners.min(axis=1), corners.max(axis=1)
    spacing = hi[0] - lo[0]
    origin = lo.min(axis=0)
    index = [np.rint((centre[:, d] - origin[d]) / spacing[d] - 0.5).astype(int) for d in range(3)]
    shape = [i.max() + 1 for i in index]
    # the layer of cells (constant y index) whose centres are nearest to the axis y = 0
    sel = index[1] == np.argmin(np.abs(origin[1] + (np.arange(shape[1]) + 0.5) * spacing[1]))
    extent = [origin[0], origin[0] + shape[0] * spacing[0], origin[2], origin[2] + shape[2] * spacing[2]]
    return centre, sel, index, shape, extent


def slice_of(values, sel, index, shape):
    plane = np.full((shape[2], shape[0]), np.nan)
    plane[index[2][sel], index[0][sel]] = values[sel]
    return plane


snapshots = sorted(glob.glob(os.path.join(folder, "fields_[0-9]*.h5")))
picked = [snapshots[int(i)] for i in np.linspace(0, len(snapshots) - 1, min(6, len(snapshots)))] if snapshots else []
if picked:
    centre, sel, index, shape, extent = mid_plane(os.path.join(folder, "fields_mesh.h5"))
    fig, axes = plt.subplots(1, len(picked), figsize=(1.6 * len(picked) + 1, 7), squeeze=False)
    for ax, path in zip(axes[0], picked):
        with h5py.File(path, "r") as f:
            solids = 1.0 - np.asarray(f["gas_fraction"])
            time = float(np.asarray(f["time"])[0])
        image = ax.imshow(slice_of(solids, sel, index, shape), origin="lower", extent=extent, vmin=0, vmax=0.6,
                          cmap="viridis", aspect="auto")
        ax.set_title(f"t = {time:.1f} s", fontsize=8)
        ax.set_xticks([])
    axes[0][0].set_ylabel("z [m]")
    fig.colorbar(image, ax=axes[0].tolist(), shrink=0.6, label="solids fraction")
    fig.suptitle("solids fraction on the mid plane (paper, Figure 4)")
    save(fig, "fcc_solids_fraction.png")

averaged = sorted(glob.glob(os.path.join(folder, "averages_[0-9]*.h5")))
if averaged:
    centre, sel, index, shape, extent = mid_plane(os.path.join(folder, "averages_mesh.h5"))
    with h5py.File(averaged[-1], "r") as f:
        fields = {k: np.asarray(f[k]) for k in ("mean_solids_fraction", "mean_gas_speed", "mean_solids_speed")}
    fig, axes = plt.subplots(1, 3, figsize=(9, 7), layout="constrained")
    for ax, (name, values) in zip(axes, fields.items()):
        image = ax.imshow(slice_of(values, sel, index, shape), origin="lower", extent=extent, cmap="viridis",
                          aspect="auto", vmin=0, vmax=np.nanpercentile(values, 99) if name != "mean_solids_fraction" else 0.6)
        ax.set_title(name.replace("_", " "), fontsize=9)
        ax.set_xticks([])
        fig.colorbar(image, ax=ax, shrink=0.6)
    axes[0].set_ylabel("z [m]")
    fig.suptitle("time averages on the mid plane (paper, Figure 7)")
    save(fig, "fcc_averaged_fields.png")
    # Below / above the sparger and in the exit tube (the tube: cells above the highest wall of the column,
    # i.e. the layers narrower than the column).
    z = centre[:, 2]
    per_layer = {round(v, 9): np.sum(np.isclose(z, v)) for v in np.unique(z)}
    widest = max(per_layer.values())
    tube = np.array([per_layer[round(v, 9)] < 0.5 * widest for v in z])
    solids_speed, solids = fields["mean_solids_speed"], fields["mean_solids_fraction"]
    print("time-averaged solids speed (cells with mean solids fraction > 0.05): " + ", ".join(
        f"{lo_z:.1f}-{hi_z:.1f} m: {solids_speed[(z >= lo_z) & (z < hi_z) & (solids > 0.05)].mean():.3f} m/s"
        for lo_z, hi_z in ((0.0, 0.25), (0.35, 1.0), (1.0, 2.0)) if ((z >= lo_z) & (z < hi_z) & (solids > 0.05)).any()))
    if tube.any():
        print(f"time-averaged gas speed in the exit tube: {fields['mean_gas_speed'][tube].mean():.2f} m/s "
              f"(largest {fields['mean_gas_speed'][tube].max():.2f} m/s)")
for path in written:
    print(f"plot written: {path}")
