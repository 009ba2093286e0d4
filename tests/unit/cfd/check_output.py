#!/usr/bin/env python3
"""Reads the gas output written by cfd_output_test on 1, 2 and 3 ranks with h5py and checks it:
cell centres from the hexahedra match the written centres, ids match global_id, a_g matches its
formula, the XDMF index references existing datasets, and all rank counts give the same fields. The cut-cell
runs (cut_npN): the fluid fraction is in (0, 1], 1 in whole cells, the boxes' fluid volume (fraction x box)
is the cell's volume (a merged cell's spread over its members' boxes), the fluid volume is the 128-gon
column's, and every centroid lies in its cell's box (the box drawn is the background cell's)."""
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np



def check_cut_cells(corners, centroid, volume, fraction):
    """corners: (n, 8, 3) of each cell's box; the column of output_test.cpp (R 0.05 m, 0.2 m tall, 128-gon)."""
    lo, hi = corners.min(axis=1), corners.max(axis=1)
    box = np.prod(hi - lo, axis=1)
    assert np.all(fraction > 0) and np.all(fraction <= 1 + 1e-14), "fluid fraction outside (0, 1]"
    assert np.any(fraction < 0.99) and np.any(fraction == 1.0), "expected cut and whole cells"
    whole = fraction == 1.0
    assert np.abs(centroid[whole] - corners[whole].mean(axis=1)).max() < 1e-14, "whole cells' centres"
    spread = fraction * box  # a merged cell's volume over its members' boxes: less than its volume
    single = np.isclose(spread, volume, rtol=1e-12, atol=0)
    assert np.all(spread[~single] < volume[~single]), "fraction x box above the cell's volume"
    inside = np.all((centroid[single] >= lo[single] - 1e-12) & (centroid[single] <= hi[single] + 1e-12), axis=1)
    assert np.all(inside), "a centroid outside its cell's box"
    polygon = 0.5 * 128 * np.sin(2 * np.pi / 128) * 0.05**2 * 0.2
    assert abs(volume.sum() / polygon - 1) < 1e-10, (volume.sum(), polygon)
    print(f"  cut cells: {np.count_nonzero(~whole)} cut, {np.count_nonzero(~single)} merged; fluid volume / "
          f"128-gon column {volume.sum() / polygon - 1:+.1e}; fraction {fraction.min():.4f}-{fraction.max():.4f}")


root = sys.argv[1]
results = {}
for run in sorted(os.listdir(root)):
    d = os.path.join(root, run)
    with h5py.File(os.path.join(d, "gas_mesh.h5"), "r") as mesh:
        points = mesh["points"][...]
        cells = mesh["cells"][...]
        gid = mesh["global_id"][...]
        fraction = mesh["fluid_fraction"][...]
    n = len(gid)
    assert cells.shape == (n, 8) and points.shape == (8 * n, 3)
    centres = points[cells].mean(axis=1)
    xdmf = ET.parse(os.path.join(d, "gas.xdmf"))
    grids = xdmf.findall(".//Grid[@GridType='Uniform']")
    assert len(grids) == 2, "expected two snapshots in the XDMF index"
    for item in xdmf.iter("DataItem"):
        fname, dset = item.text.strip().split(":")
        with h5py.File(os.path.join(d, fname), "r") as f:
            assert dset.lstrip("/") in f, item.text
            dims = [int(v) for v in item.get("Dimensions").split()]
            assert list(f[dset].shape) == dims, (item.text, f[dset].shape, dims)
    with h5py.File(os.path.join(d, "gas_000001.h5"), "r") as f:
        assert abs(f["time"][0] - 0.02) < 1e-15
        assert np.array_equal(f["id_check"][...], gid.astype(float)), "ids out of place"
        written = f["centre_check"][...]
        if run.startswith("cut_"):
            check_cut_cells(points[cells], written, f["volume_check"][...], fraction)
        else:
            assert np.abs(written - centres).max() < 1e-14, "centres out of place"
            assert np.all(fraction == 1.0), "staircase cells are whole"
        expected = 1.0 - 0.3 * np.sin(20 * written[:, 2]) ** 2
        assert np.abs(f["a_g"][...] - expected).max() < 1e-14, "a_g values wrong"
        order = np.argsort(gid)
        results[run] = (f["p"][...][order], f["u"][...][order])
    print(f"{run}: {n} cells, 2 snapshots, values and XDMF index consistent")
for run, (p, u) in results.items():
    ref = results.get(run[: run.index("np")] + "np1")
    if ref is None or run.endswith("np1"):
        continue
    dp = np.abs(p - ref[0]).max() / np.abs(ref[0]).max()
    du = np.abs(u - ref[1]).max() / max(np.abs(ref[1]).max(), 1e-300)
    print(f"[measured] output {run} vs np1: max relative difference p {dp:.3e}, u {du:.3e}")
    assert dp < 1e-10 and du < 1e-10
print("check_output: OK")
