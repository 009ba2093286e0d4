"""Run by pvpython (paraview_test.py): opens FOLDER/fields.xdmf and FOLDER/parcels.xdmf with the reader
ParaView picks (Xdmf3ReaderS) and with the XDMF (2) reader, and compares times, point and cell counts,
array names and per-component ranges with FOLDER/expected.json. The XDMF (2) reader reports an error for
a snapshot without parcels and shows it empty, so it is checked on the non-empty ones only."""
import json
import os
import sys

from paraview.simple import OpenDataFile, XDMFReader

folder = sys.argv[1]
expected = json.load(open(os.path.join(folder, "expected.json")))
failures = []
for name, snapshots in expected.items():
    path = os.path.join(folder, name + ".xdmf")
    for reader_name, reader in (("default", OpenDataFile(path)), ("XDMFReader", XDMFReader(FileNames=[path]))):
        times = list(reader.TimestepValues)
        if [round(t, 12) for t in times] != [round(s["time"], 12) for s in snapshots]:
            failures.append(f"{name} {reader_name}: times {times}")
        for s in snapshots:
            if reader_name == "XDMFReader" and s["cells"] == 0:
                continue
            reader.UpdatePipeline(s["time"])
            info = reader.GetDataInformation()
            data = reader.CellData if name == "fields" else reader.PointData
            seen = {k: [list(data[k].GetRange(c)) for c in range(data[k].GetNumberOfComponents())]
                    for k in data.keys()}
            where = f"{name} t={s['time']} ({reader.GetXMLName()})"
            if (info.GetNumberOfPoints(), info.GetNumberOfCells()) != (s["points"], s["cells"]):
                failures.append(f"{where}: {info.GetNumberOfPoints()} points, {info.GetNumberOfCells()} cells")
            if sorted(seen) != sorted(s["arrays"]):
                failures.append(f"{where}: arrays {sorted(seen)}, expected {sorted(s['arrays'])}")
            for k, ranges in s["arrays"].items():
                if k in seen and any(abs(a - b) > 1e-12 * max(1.0, abs(b))
                                     for got, want in zip(seen[k], ranges) for a, b in zip(got, want)):
                    failures.append(f"{where}: {k} range {seen[k]}, expected {ranges}")
            print(f"{where}: {info.GetNumberOfPoints()} points, {info.GetNumberOfCells()} cells, "
                  f"arrays {sorted(seen)}")
print("\n".join(failures) if failures else "paraview_check: OK")
sys.exit(1 if failures else 0)
