#!/usr/bin/python3
"""Reads a ParcelWriter series with h5py and checks it against what parcel_writer_test wrote.
usage: check_parcels.py DIR TIME:COUNT...  (one TIME:COUNT per expected snapshot, in order)
Checks: the XDMF index parses, lists exactly the expected snapshots and references existing datasets
with matching dimensions and types; each file's time, shapes, unique ids in rank order, values and
vertex connectivity."""
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

folder, expected = sys.argv[1], [(float(t), int(n)) for t, n in (a.split(":") for a in sys.argv[2:])]
assert not os.path.exists(os.path.join(folder, "parcels.xdmf.partial")), "temporary index left behind"
grids = ET.parse(os.path.join(folder, "parcels.xdmf")).findall(".//Grid[@GridType='Uniform']")
assert len(grids) == len(expected), f"{len(grids)} snapshots in the index, expected {len(expected)}"
for index, (grid, (time, count)) in enumerate(zip(grids, expected)):
    name = f"parcels_{index:06d}.h5"
    assert abs(float(grid.find("Time").get("Value")) - time) < 1e-12, (name, "time in the index")
    topology = grid.find("Topology")
    assert topology.get("TopologyType") == "Polyvertex" and int(topology.get("NumberOfElements")) == count
    with h5py.File(os.path.join(folder, name), "r") as f:
        for item in grid.iter("DataItem"):
            file, dataset = item.text.strip().split(":")
            assert file == name and dataset.lstrip("/") in f, item.text
            data = f[dataset]
            assert list(data.shape) == [int(d) for d in item.get("Dimensions").split()], item.text
            kind = "Int" if data.dtype.kind == "i" else "Float"
            assert (item.get("NumberType"), int(item.get("Precision"))) == (kind, data.dtype.itemsize), item.text
        assert abs(f["time"][0] - time) < 1e-15, (name, "time")
        ids = f["id"][...]
        assert ids.shape == (count,) and f["position"].shape == (count, 3), (name, "shapes")
        assert len(np.unique(ids)) == count, (name, "ids not unique")
        assert np.all(np.diff(ids) > 0), (name, "rows not in rank order")
        k = ids.astype(float)
        assert np.array_equal(f["position"][...], np.column_stack([1e-3 * k, 2e-3 * k, 3e-3 * k]))
        assert np.array_equal(f["velocity"][...], np.column_stack([-k, 0.5 * k, 0.25 * k]))
        assert np.array_equal(f["dp"][...], 1e-3 * (1 + ids % 3))
        assert np.array_equal(f["np"][...], 8.0 + k)
        assert np.array_equal(f["type"][...], 1 + ids % 2) and f["type"].dtype == np.int32
        assert np.array_equal(f["connectivity"][...], np.arange(count)), (name, "connectivity")
    print(f"{name}: t = {time}, {count} parcels: index, shapes, ids and values consistent")
print("check_parcels: OK")
