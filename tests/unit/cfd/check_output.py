#!/usr/bin/env python3
"""Reads the gas output written by cfd_output_test on 1, 2 and 3 ranks with h5py and checks it:
cell centres from the hexahedra match the written centres, ids match global_id, a_g matches its
formula, the XDMF index references existing datasets, and all rank counts give the same fields."""
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

root = sys.argv[1]
results = {}
for run in sorted(os.listdir(root)):
    d = os.path.join(root, run)
    with h5py.File(os.path.join(d, "gas_mesh.h5"), "r") as mesh:
        points = mesh["points"][...]
        cells = mesh["cells"][...]
        gid = mesh["global_id"][...]
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
        assert np.abs(f["centre_check"][...] - centres).max() < 1e-14, "centres out of place"
        expected = 1.0 - 0.3 * np.sin(20 * centres[:, 2]) ** 2
        assert np.abs(f["a_g"][...] - expected).max() < 1e-14, "a_g values wrong"
        order = np.argsort(gid)
        results[run] = (f["p"][...][order], f["u"][...][order])
    print(f"{run}: {n} cells, 2 snapshots, values and XDMF index consistent")
ref = results.get("np1")
for run, (p, u) in results.items():
    if ref is None or run == "np1":
        continue
    dp = np.abs(p - ref[0]).max() / np.abs(ref[0]).max()
    du = np.abs(u - ref[1]).max() / max(np.abs(ref[1]).max(), 1e-300)
    print(f"[measured] output {run} vs np1: max relative difference p {dp:.3e}, u {du:.3e}")
    assert dp < 1e-10 and du < 1e-10
print("check_output: OK")
