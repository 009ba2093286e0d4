"""The report's figures, one function per PNG; each takes what report.py read and measured and returns the path
it wrote."""
import os

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SOLIDS_MAX = 0.65  # colour scale of the solids fraction: about random close packing


def save(fig, out, name):
    path = os.path.join(out, name)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def _shade(ax, start, end):
    ax.axvspan(start, end, color="0.9", zorder=0, label="statistics window")
    ax.set_xlim(right=end)


def pressure_drop(monitors, start, out, name="pressure_drop.png", title=""):
    """The bed pressure drop against the buoyant bed weight per area, and their ratio, over time."""
    t, dp, weight = monitors["time"], monitors["bed_pressure_drop"], monitors["bed_weight_per_area"]
    fig, (a, b) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    a.plot(t, dp, lw=0.7, label="bed pressure drop (bed_pressure_drop)")
    a.plot(t, weight, lw=1.4, label="buoyant bed weight per area (bed_weight_per_area)")
    a.set_ylabel("Pa")
    a.legend(fontsize=8, loc="lower right")
    with np.errstate(divide="ignore", invalid="ignore"):
        b.plot(t, dp / weight, lw=0.7)
    b.axhline(1.0, color="gray", lw=0.8, ls="--")
    b.set_ylim(0, 2)
    b.set_ylabel("pressure drop / weight per area")
    b.set_xlabel("time [s]")
    for ax in (a, b):
        _shade(ax, start, t[-1])
    fig.suptitle(title or "bed pressure drop against the bed weight")
    fig.tight_layout()
    return save(fig, out, name)


def class_heights(monitors, columns, start, out, name="class_heights.png", title="", labels=None):
    """The mean height of each class or atom type (the mean_z_* columns) over time, in mm."""
    fig, ax = plt.subplots(figsize=(8, 4))
    for k in columns:
        ax.plot(monitors["time"], 1000 * monitors[k], lw=0.8, label=(labels or {}).get(k, k))
    _shade(ax, start, monitors["time"][-1])
    ax.set_ylabel("mean height [mm]")
    ax.set_xlabel("time [s]")
    ax.legend(fontsize=8)
    fig.suptitle(title or "mean height of each class")
    fig.tight_layout()
    return save(fig, out, name)


def parcel_profiles(parcels, time, out, name="parcel_profiles.png", title="", labels=None, bins=30):
    """The solid volume of each atom type per height bin at one parcel snapshot (read_parcels), each type's
    profile normalised to its own total: where each class sits in the bed."""
    fig, ax = plt.subplots(figsize=(5, 6))
    edges = np.linspace(parcels["z"].min(), parcels["z"].max() + 1e-12, bins + 1)
    for kind in np.unique(parcels["type"]):
        mine = parcels["type"] == kind
        volume, _ = np.histogram(parcels["z"][mine], edges, weights=parcels["solid_volume"][mine])
        ax.plot(volume / volume.sum() / np.diff(edges), 0.5 * (edges[1:] + edges[:-1]), lw=1.2,
                label=(labels or {}).get(f"mean_z_type{kind}", f"type {kind}"))
    ax.set_xlabel("share of the type's solid volume per m of height [1/m]")
    ax.set_ylabel("z [m]")
    ax.legend(fontsize=8)
    fig.suptitle(title or f"where each type sits, t = {time:.4g} s", fontsize=10)
    if title:
        ax.set_title(f"parcels at t = {time:.4g} s", fontsize=9)
    fig.tight_layout()
    return save(fig, out, name)


def solids_planes(mesh, snapshots, out, name="solids_fraction.png", title=""):
    """The solids fraction on the vertical mid-depth plane at each snapshot [(time, gas_fraction per cell)],
    cropped above the highest solids of any of them."""
    planes = [(time, 1.0 - mesh.plane(gas_fraction)) for time, gas_fraction in snapshots]
    extent = mesh.extent()
    top = extent[3]
    rows = [np.nonzero(np.nan_to_num(p).max(axis=1) > 0.05)[0] for _, p in planes]
    highest = max((r.max() for r in rows if len(r)), default=None)
    if highest is not None:
        top = min(top, extent[2] + 1.5 * (highest + 1) * mesh.spacing[2])
    aspect = (top - extent[2]) / (extent[1] - extent[0])
    width = min(2.4, max(1.2, 6.0 / aspect))
    fig, axes = plt.subplots(1, len(planes), figsize=(max(5.0, width * len(planes) + 1.2), 6), squeeze=False,
                             sharey=True)
    image = None
    for ax, (time, plane) in zip(axes[0], planes):
        image = ax.imshow(plane, origin="lower", extent=extent, vmin=0, vmax=SOLIDS_MAX, cmap="viridis",
                          aspect="auto")
        ax.set_ylim(extent[2], top)
        ax.set_title(f"t = {time:.3g} s", fontsize=8)
        ax.set_xticks([])
    axes[0][0].set_ylabel("z [m]")
    fig.colorbar(image, ax=axes[0].tolist(), shrink=0.7, label="solids fraction")
    fig.suptitle(title or "solids fraction on the vertical mid-depth plane", fontsize=10)
    return save(fig, out, name)


def voids(rows, start, out, name="voids.png", title=""):
    """Per snapshot (report.void_rows): the voids' share of the bed's cells and the bubbles counted per plane."""
    t, share, bubbles, layer = (np.array([r[k] for r in rows], dtype=float)
                                for k in ("time", "void_share", "bubbles", "layer"))
    fig, (a, b) = plt.subplots(2, 1, figsize=(8, 5), sharex=True)
    a.plot(t, share, "o-", ms=3, lw=0.8)
    a.set_ylabel("void share of the bed")
    b.plot(t, bubbles, "o-", ms=3, lw=0.8, label="bubbles per plane")
    if layer.any():
        b.plot(t[layer > 0], bubbles[layer > 0], "rx", label="a plane with a bed-wide layer")
    b.set_ylabel("bubbles per plane")
    b.set_xlabel("time [s]")
    b.legend(fontsize=8)
    for ax in (a, b):
        ax.set_xlim(t.min() - 1e-9, t.max() + 1e-9)
        _shade(ax, start, t.max() + 1e-9)
    fig.suptitle(title or "voids in the bed (gas fraction above 0.7, at least 4 cells)")
    fig.tight_layout()
    return save(fig, out, name)


def averaged_profile(header, columns, out, name="averages_profile.png"):
    """averages.csv: the time-averaged pressure on the planes and dp/(g dz) between them against height."""
    fig, (a, b) = plt.subplots(1, 2, figsize=(9, 6), sharey=True)
    a.plot(columns["dp_over_g_dz"], columns["interval_mid_z"], "o-", ms=3)
    a.set_xlabel("dp / (g dz) [kg/m3]")
    a.set_ylabel("height z [m]")
    b.plot(columns["mean_pressure"] / 1000, columns["z"], "o-", ms=3)
    b.set_xlabel("time-averaged pressure [kPa]")
    for ax in (a, b):
        ax.grid(alpha=0.3)
    fig.suptitle(header.lstrip("# "), fontsize=9)
    fig.tight_layout()
    return save(fig, out, name)


def averaged_fields(mesh, fields, time, out, name="averages_fields.png"):
    """The time-averaged fields {name: per cell} on the vertical mid-depth plane."""
    fig, axes = plt.subplots(1, len(fields), figsize=(3 * len(fields) + 1, 6), squeeze=False, layout="constrained")
    for ax, (key, values) in zip(axes[0], fields.items()):
        finite = values[np.isfinite(values)]
        top = SOLIDS_MAX if "solids_fraction" in key else (np.percentile(finite, 99) if finite.size else 1.0)
        image = ax.imshow(mesh.plane(values), origin="lower", extent=mesh.extent(), vmin=0, vmax=max(top, 1e-12),
                          cmap="viridis", aspect="auto")
        ax.set_title(key.replace("_", " "), fontsize=9)
        ax.set_xticks([])
        fig.colorbar(image, ax=ax, shrink=0.6)
    axes[0][0].set_ylabel("z [m]")
    fig.suptitle(f"time averages on the vertical mid-depth plane, written at t = {time:.4g} s")
    return save(fig, out, name)
