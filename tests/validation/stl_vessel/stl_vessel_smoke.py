#!/usr/bin/python3
"""Smoke test of cases/stl_vessel (issue 31: a vessel from one STL file for the gas and the parcels): 0.2 s on the
ranks given, in a temporary copy of the case that is removed at the end. Checks that the run ends, that no parcel
is lost, that no parcel starts outside the geometry or the fluid cells (no such warnings: the two codes read one
surface), and that the bed's pressure drop over 0.1-0.2 s is its weight within 20 % (1 m/s, about twice the
beads' minimum fluidization: the gas carries the bed; measured 0.97 on 1 rank).

With `--geometry primitive` the copy describes the vessel as a `cylinder` in case.yaml (radius 25 mm, 0-150 mm)
and its script takes the parcels' walls from `${geometry_stl}` (the surface parcelflow writes of case.yaml's
geometry, coupling/README.md) instead of vessel.stl, which is removed: the same checks then show that the walls
parcelflow generates from primitives are the gas's.

usage: stl_vessel_smoke.py [--geometry primitive] PARCELFLOW MPIEXEC..."""
import csv
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, copy_case, fail  # noqa: E402


def from_primitive(settings):
    settings["geometry"] = [{"shape": {"cylinder": {"center": [0, 0], "radius": 0.025, "zmin": 0.0, "zmax": 0.15}}}]


def walls_from_geometry_stl(case):
    os.remove(os.path.join(case, "vessel.stl"))
    script = os.path.join(case, "vessel.in")
    text = open(script).read()
    if "mesh/surface file vessel.stl" not in text:
        fail("vessel.in no longer reads vessel.stl: update this test")
    open(script, "w").write(text.replace("mesh/surface file vessel.stl", "mesh/surface file ${geometry_stl}"))


def main():
    args = sys.argv[1:]
    primitive = args[:2] == ["--geometry", "primitive"]
    if primitive:
        args = args[2:]
    parcelflow, launcher = args[0], args[1:]
    work = tempfile.mkdtemp(prefix="pf_stl_vessel_")
    try:
        def edit(settings):
            settings["time"]["end"] = 0.2
            if primitive:
                from_primitive(settings)
        case = copy_case(os.path.join(CASES, "stl_vessel"), work, edit,
                         walls_from_geometry_stl if primitive else lambda case: None)
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
                fail(f"a start-up warning with '{words}': the gas's and the parcels' walls disagree")
        if primitive and not os.path.isfile(os.path.join(out, "geometry.stl")):
            fail("no geometry.stl in the output folder")
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
