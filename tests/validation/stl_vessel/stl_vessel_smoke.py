#!/usr/bin/python3
"""Smoke test of cases/stl_vessel (issue 31: a vessel from one STL file for the gas and the parcels): 0.2 s on the
ranks given, in a temporary copy of the case that is removed at the end. Checks that the run ends, that no parcel
is lost, that no parcel starts outside the geometry or the fluid cells (no such warnings: the two codes read one
surface), and that the bed's pressure drop over 0.1-0.2 s is its weight within 20 % (1 m/s, about twice the
beads' minimum fluidization: the gas carries the bed; measured 0.97 on 1 rank).

usage: stl_vessel_smoke.py PARCELFLOW MPIEXEC..."""
import csv
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, copy_case, fail  # noqa: E402


def main():
    parcelflow, launcher = sys.argv[1], sys.argv[2:]
    work = tempfile.mkdtemp(prefix="pf_stl_vessel_")
    try:
        case = copy_case(os.path.join(CASES, "stl_vessel"), work, lambda s: s["time"].update(end=0.2))
        out = os.path.join(work, "output")
        done = subprocess.run(launcher + [parcelflow, "run", case, "--output", out], capture_output=True, text=True,
                              errors="replace")
        if done.returncode != 0:
            fail(f"parcelflow exited with {done.returncode}\n{done.stdout[-3000:]}{done.stderr[-3000:]}")
        summary = [l for l in done.stdout.splitlines() if l.startswith("parcelflow: done")][-1]
        print(summary)
        lost = int(re.search(r"(\d+) parcels lost", summary).group(1))
        if lost:
            fail(f"{lost} parcels lost")
        for words in ("outside case.yaml's geometry", "in no fluid cell"):
            if words in done.stdout:
                fail(f"a start-up warning with '{words}': the STL's two readers disagree")
        rows = [r for r in csv.DictReader(open(os.path.join(out, "monitors.csv"))) if float(r["time"]) >= 0.1]
        ratio = sum(float(r["bed_pressure_drop"]) / float(r["bed_weight_per_area"]) for r in rows) / len(rows)
        print(f"[measured] bed pressure drop / weight over 0.1-0.2 s: {ratio:.3f} ({len(rows)} rows)")
        if not 0.8 < ratio < 1.2:
            fail(f"the bed's pressure drop is {ratio:.3f} of its weight, expected 1 within 20 %")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("PASS")


if __name__ == "__main__":
    main()
