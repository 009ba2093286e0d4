"""What a parcelflow run wrote into its output folder, read for the report.

- monitors.csv: one row per monitor interval, a column per monitored quantity (coupling/monitors);
- fields_mesh.h5 + fields_NNNNNN.h5 (+ fields.xdmf): the gas cells as hexahedra (8 corner points each) and,
  per snapshot, its time and per-cell gas_fraction (and gas_velocity, solids_velocity, pressure);
- averages.csv, averages_mesh.h5 + averages_NNNNNN.h5: the time averages of monitors.average;
- parcels_NNNNNN.h5: position, velocity, dp, np, type, id per parcel.
The mesh is a Cartesian background grid; with cut cells (mesh.walls: cut_cells) only the cells in the gas are
written, so a plane of cells has holes (NaN) outside the vessel.
"""
import csv
import glob
import os

import h5py
import numpy as np


class NotARun(Exception):
    """The folder is not a run's output folder, or a file in it is not what parcelflow writes."""


def read_monitors(folder):
    """monitors.csv as {column: numpy array}, in the order of its header."""
    path = os.path.join(folder, "monitors.csv")
    if not os.path.isfile(path):
        raise NotARun(f"{folder}: no monitors.csv (not a run's output folder)")
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if len(rows) < 2 or rows[0][:1] != ["time"]:
        raise NotARun(f"{path}: needs a header starting with 'time' and at least one row")
    header, body = rows[0], [r for r in rows[1:] if len(r) == len(rows[0])]
    values = np.array(body, dtype=float).reshape(len(body), len(header))
    return {name: values[:, k] for k, name in enumerate(header)}


def height_columns(monitors):
    """The mean_z_* columns (mean height of each atom type or class) that hold a finite value."""
    return [k for k in monitors if k.startswith("mean_z_") and np.isfinite(monitors[k]).any()]


def series(folder, name):
    """[(time, path), ...] of the snapshots NAME_NNNNNN.h5 (fields, averages, parcels), in time order."""
    out = []
    for path in glob.glob(os.path.join(folder, f"{name}_[0-9]*.h5")):
        with h5py.File(path, "r") as f:
            out.append((float(np.asarray(f["time"])[0]), path))
    return sorted(out)


def read_field(path, name):
    """One per-cell dataset of a snapshot file (None when the file lacks it)."""
    with h5py.File(path, "r") as f:
        return np.asarray(f[name]) if name in f else None


def read_parcels(path):
    """One parcel snapshot as {"z": heights, "type": atom types, "solid_volume": np pi dp^3 / 6 per parcel}."""
    with h5py.File(path, "r") as f:
        dp, count = np.asarray(f["dp"]), np.asarray(f["np"])
        return {"z": np.asarray(f["position"])[:, 2], "type": np.asarray(f["type"]),
                "solid_volume": count * np.pi / 6 * dp ** 3}


class Mesh:
    """The written cells of NAME_mesh.h5 on their background grid: index[d] (cell index along x, y, z), shape,
    spacing, origin. The plane of the report is vertical, along the wider horizontal axis (width_axis) at a
    height of cells, sliced across the other one (depth_axis)."""

    def __init__(self, path):
        if not os.path.isfile(path):
            raise NotARun(f"{path}: missing (the field snapshots need their mesh file)")
        with h5py.File(path, "r") as f:
            corners = np.asarray(f["points"]).reshape(-1, 8, 3)
        lo, hi = corners.min(axis=1), corners.max(axis=1)
        self.centres = 0.5 * (lo + hi)
        self.spacing = (hi - lo).max(axis=0)
        self.origin = lo.min(axis=0)
        self.index = [np.rint((lo[:, d] - self.origin[d]) / self.spacing[d]).astype(int) for d in range(3)]
        self.shape = [int(i.max()) + 1 for i in self.index]
        extent = [self.shape[d] * self.spacing[d] for d in range(2)]
        self.width_axis = 0 if extent[0] >= extent[1] else 1
        self.depth_axis = 1 - self.width_axis
        self.box = len(self.centres) == np.prod(self.shape)  # every background cell written: no cut cells

    @property
    def width(self):
        return self.shape[self.width_axis] * self.spacing[self.width_axis]

    @property
    def depth(self):
        return self.shape[self.depth_axis] * self.spacing[self.depth_axis]

    def extent(self):
        """[w0, w1, z0, z1] of the plane, for imshow."""
        w, z = self.width_axis, 2
        return [self.origin[w], self.origin[w] + self.width, self.origin[z], self.origin[z] + self.shape[z] * self.spacing[z]]

    def thin(self):
        """A quasi-2D bed (depth at most a quarter of its width): its voids are measured on the depth average."""
        return self.depth <= 0.25 * self.width

    def plane(self, values, fraction=0.5):
        """values per cell on the row of cells at fraction of the depth, as a[z, w] (NaN where no cell)."""
        j = min(self.shape[self.depth_axis] - 1, int(fraction * self.shape[self.depth_axis]))
        on = self.index[self.depth_axis] == j
        a = np.full((self.shape[2], self.shape[self.width_axis]), np.nan)
        a[self.index[2][on], self.index[self.width_axis][on]] = values[on]
        return a

    def depth_average(self, values):
        """values per cell averaged over the cells across the depth, as a[z, w] (NaN where no cell)."""
        total = np.zeros((self.shape[2], self.shape[self.width_axis]))
        count = np.zeros_like(total)
        at = (self.index[2], self.index[self.width_axis])
        np.add.at(total, at, values)
        np.add.at(count, at, 1)
        with np.errstate(invalid="ignore"):
            return np.where(count > 0, total / np.maximum(count, 1), np.nan)

    def void_planes(self, gas_fraction, slices=(0.25, 0.5, 0.75)):
        """The planes the voids are measured on: the depth average of a thin bed, else the slices."""
        if self.thin():
            return [self.depth_average(gas_fraction)]
        return [self.plane(gas_fraction, f) for f in slices]

    def width_first(self, vectors):
        """Vectors per cell (n, 3) with the width axis first, the depth axis second (mesoscale.py's x, y)."""
        return vectors[:, [self.width_axis, self.depth_axis, 2]]


def read_averages_csv(folder):
    """averages.csv as (header line, {column: array}); None without the file."""
    path = os.path.join(folder, "averages.csv")
    if not os.path.isfile(path):
        return None
    with open(path) as f:
        lines = f.read().splitlines()
    rows = list(csv.DictReader(lines[1:]))
    columns = {k: np.array([float(r[k]) if r[k] else np.nan for r in rows]) for k in rows[0]} if rows else {}
    return lines[0], columns
