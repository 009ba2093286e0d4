#!/usr/bin/python3
"""The report of a real run: cases/fluidized_column coupled for 0.06 s with a field snapshot every 0.01 s,
then cases/report/report.py on its output and the case's plot.py.
Checks: report.py exits 0 and writes report.txt and non-empty PNGs of the pressure drop, the class heights,
the solids fraction and the voids; its dp/(W/A) and the parcels' mean height over the second half equal those
computed here from monitors.csv; the voids are measured on the snapshots of the second half (the 20 mm square
column is measured on three slices) with a void share in [0, 1]; the solids fraction on the mid-depth plane
lies in [0, 1) where there are cells; plot.py writes its PNGs into the run folder. The temporary folder is
removed at the end.
usage: report_fluidized_column.py PARCELFLOW MPIEXEC..."""
import csv
import os
import re
import sys
import tempfile

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, copy_case, expect_nothing_left, fail, run  # noqa: E402

END, FIELDS = 0.06, 0.01
REPORT = os.path.join(CASES, "report", "report.py")


def edit(settings):
    settings["output"].update({"fields_interval": FIELDS, "progress_interval": 1e6})


def png_ok(path):
    if not os.path.isfile(path) or os.path.getsize(path) < 1000:
        return False
    with open(path, "rb") as f:
        return f.read(4) == b"\x89PNG"


def main():
    parcelflow, launcher = sys.argv[1], sys.argv[2:]
    here_before = set(os.listdir("."))
    with tempfile.TemporaryDirectory(prefix="pf_report_run_") as work:
        case = copy_case(os.path.join(CASES, "fluidized_column"), work, edit)
        out = os.path.join(work, "output")
        run(launcher + [parcelflow, "run", case, "--output", out, "--end", str(END)])
        report_dir = os.path.join(work, "report")
        text = run([sys.executable, REPORT, out, "--out", report_dir])
        print(text)
        check_report(out, report_dir, text)
        plot = run([sys.executable, os.path.join(CASES, "fluidized_column", "plot.py"), out])
        for name in ("pressure_drop", "class_heights", "solids_fraction", "voids"):
            if not png_ok(os.path.join(out, name + ".png")):
                fail(f"plot.py wrote no {name}.png into the run folder\n{plot}")
    expect_nothing_left(work, here_before)
    print("PASS")


def check_report(out, report_dir, text):
    for name in ("pressure_drop", "class_heights", "solids_fraction", "voids"):
        if not png_ok(os.path.join(report_dir, name + ".png")):
            fail(f"report.py wrote no non-empty {name}.png")
    with open(os.path.join(report_dir, "report.txt")) as f:
        if f.read().strip() not in text:
            fail("report.txt is not the summary report.py printed")
    with open(os.path.join(out, "monitors.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    t = np.array([float(r["time"]) for r in rows])
    window = t >= 0.5 * t[-1]
    dp = np.array([float(r["bed_pressure_drop"]) for r in rows])[window]
    weight = np.array([float(r["bed_weight_per_area"]) for r in rows])[window]
    height = 1000 * np.array([float(r["mean_z_type1"]) for r in rows])[window]
    expected = (f"dp/(W/A) {dp.mean() / weight.mean():.3f}, rms {dp.std() / weight.mean():.3f}",
                f"mean_z_type1 {height.mean():.2f}, {height.std():.2f}")
    print(f"[measured] second half: dp/(W/A) {dp.mean() / weight.mean():.4f}, mean height {height.mean():.3f} mm")
    for words in expected:
        if words not in text:
            fail(f"the report does not say '{words}' (computed here from monitors.csv)")
    snapshots = sorted(n for n in os.listdir(out) if re.fullmatch(r"fields_\d+\.h5", n))
    times = []
    for name in snapshots:
        with h5py.File(os.path.join(out, name), "r") as f:
            times.append(float(f["time"][0]))
    in_window = sum(1 for time in times if time >= 0.5 * t[-1] - 1e-12)
    found = re.search(r"voids on slices at 1/4, 1/2, 3/4 of the depth, (\d+) snapshots: void share (\S+),", text)
    if not found:
        fail("the report measured no voids on the three slices of the square column")
    count, share = int(found.group(1)), float(found.group(2))
    if count != in_window or not 0.0 <= share <= 1.0:
        fail(f"voids over {count} snapshots (expected {in_window}, of {len(snapshots)} at {times}), void share {share}")

    sys.path.insert(0, os.path.dirname(REPORT))
    import run_output
    mesh = run_output.Mesh(os.path.join(out, "fields_mesh.h5"))
    plane = 1.0 - mesh.plane(run_output.read_field(os.path.join(out, snapshots[-1]), "gas_fraction"))
    finite = plane[np.isfinite(plane)]
    if mesh.shape != [5, 5, 25] or finite.size != 5 * 25 or finite.min() < 0 or finite.max() >= 1:
        fail(f"mid-depth plane of {mesh.shape} cells: {finite.size} cells, solids fraction {finite.min()}-"
             f"{finite.max()}")


if __name__ == "__main__":
    main()
