#!/usr/bin/python3
"""Opens cfd::FieldWriter and ParcelWriter output in a real ParaView: write_output (2 ranks) writes two
snapshots of each into a temporary folder, h5py reads what ParaView should show (times, point and cell
counts, array names and ranges), and paraview_check.py, run by pvpython, compares. Exits 77 (CTest:
skipped), saying so, where ParaView's pvpython is not installed.
usage: paraview_test.py WRITE_OUTPUT MPIEXEC [MPIEXEC FLAGS...]"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

pvpython = shutil.which("pvpython")
if pvpython is None:
    print("SKIPPED: ParaView's pvpython is not installed (Debian: apt-get install paraview python3-paraview)")
    sys.exit(77)
writer, mpiexec = sys.argv[1], sys.argv[2:]
folder = tempfile.mkdtemp(prefix="paraview_output_")
try:
    subprocess.run(mpiexec + ["-np", "2", writer, folder], check=True)
    with h5py.File(os.path.join(folder, "fields_mesh.h5"), "r") as mesh:
        cells = len(mesh["global_id"])
    expected = {}
    for name in ("fields", "parcels"):
        snapshots = []
        for i in range(2):
            with h5py.File(os.path.join(folder, f"{name}_{i:06d}.h5"), "r") as f:
                n = cells if name == "fields" else len(f["id"])
                # [min, max] of each component, as ParaView's GetRange(component) reports it
                arrays = {k: np.column_stack([f[k][...].min(axis=0), f[k][...].max(axis=0)]).reshape(-1, 2)
                          .tolist() for k in f if k not in ("time", "position", "connectivity") and n > 0}
                if name == "fields":  # every snapshot lists the mesh file's fluid fraction beside its fields
                    with h5py.File(os.path.join(folder, "fields_mesh.h5"), "r") as mesh:
                        fraction = mesh["fluid_fraction"][...]
                    arrays["fluid_fraction"] = [[float(fraction.min()), float(fraction.max())]]
                snapshots.append({"time": float(f["time"][0]), "cells": n,
                                  "points": 8 * n if name == "fields" else n, "arrays": arrays})
        expected[name] = snapshots
    assert expected["parcels"][1]["cells"] == 0, "the second parcel snapshot should be empty"
    with open(os.path.join(folder, "expected.json"), "w") as f:
        json.dump(expected, f)
    check = os.path.join(os.path.dirname(os.path.abspath(__file__)), "paraview_check.py")
    sys.exit(subprocess.run([pvpython, "--force-offscreen-rendering", check, folder]).returncode)
finally:
    shutil.rmtree(folder)
