#!/usr/bin/python3
"""Smoke test of cases/tutorial_cylinder, the bed that cases/README.md builds step by step.

1. Every line the tutorial quotes from the case (its yaml blocks and its LIGGGHTS blocks, '...' lines aside) is
   a line of case.yaml or bed.in, so the page and the case cannot drift apart.
2. A copy with 2,000 parcels and a shorter settling runs 0.01 s on the ranks given, in a temporary folder that
   is removed at the end. Checks: the run ends with exit 0 and no parcel lost; the contact time it reports is
   the tutorial's (1.96e-4 s = 19.6 DEM steps: grain t_c 1.309e-4 s times l = 1.5); the parcel report gives the
   tutorial's D/h 0.3, 33.3 parcels across and a wall-layer share below 0.05, with no parcelflow warning; monitors.csv
   reaches 0.01 s with a positive bed pressure drop and bed weight.

usage: tutorial_cylinder_smoke.py PARCELFLOW MPIEXEC..."""
import csv
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, copy_case, fail, replace_in_file  # noqa: E402

CASE = os.path.join(CASES, "tutorial_cylinder")


def quoted_lines(tutorial):
    """The lines of the tutorial's yaml blocks and unlabelled blocks that quote the case (not the run's output)."""
    block = None
    for line in open(tutorial):
        if line.startswith("```"):
            block = None if block is not None else line[3:].strip()
        elif block in ("yaml", "") and line.strip() and line.strip() != "...":
            if not line.startswith(("parcelflow:", "  mpirun")):
                yield line.rstrip("\n")


def check_tutorial_quotes():
    case_lines = set()
    for name in ("case.yaml", "bed.in"):
        case_lines |= {l.rstrip("\n") for l in open(os.path.join(CASE, name))}
    quoted = list(quoted_lines(os.path.join(CASES, "README.md")))
    missing = [l for l in quoted if l not in case_lines]
    if len(quoted) < 40 or missing:
        fail(f"cases/README.md quotes {len(quoted)} lines; not in case.yaml or bed.in: {missing}")
    print(f"cases/README.md: all {len(quoted)} quoted lines are lines of the case")


def main():
    parcelflow, launcher = sys.argv[1], sys.argv[2:]
    check_tutorial_quotes()
    work = tempfile.mkdtemp(prefix="pf_tutorial_")
    try:
        def edit(settings):
            settings["liggghts"]["variables"]["nparcels"] = "2000"
            settings["output"].update({"fields_interval": 0, "checkpoint_interval": 0})

        def shorter_settling(case):
            replace_in_file(os.path.join(case, "bed.in"), [("run             6000", "run             2500")])

        case = copy_case(CASE, work, edit, shorter_settling)
        out = os.path.join(work, "output")
        done = subprocess.run(launcher + [parcelflow, "run", case, "--output", out, "--end", "0.01"],
                              capture_output=True, text=True, errors="replace", timeout=500)
        if done.returncode != 0:
            fail(f"parcelflow exited with {done.returncode}\n{done.stdout[-3000:]}{done.stderr[-3000:]}")
        text = done.stdout + done.stderr
        summary = [l for l in done.stdout.splitlines() if l.startswith("parcelflow: done")][-1]
        print(summary)
        if int(re.search(r"(\d+) parcels lost", summary).group(1)) != 0:
            fail("parcels were lost")
        if not re.search(r"contact time 0\.000196 s .* = 19\.6 DEM steps", text):
            fail("the contact time line is not the tutorial's 0.000196 s = 19.6 DEM steps:\n" +
                 "\n".join(l for l in text.splitlines() if "contact time" in l))
        report = [l for l in text.splitlines() if l.startswith("parcelflow: coarse graining: largest parcel")]
        if not report:
            fail("no parcel report line")
        print(report[0])
        share = float(re.search(r"wall layer share .* = ([0-9.]+)", report[0]).group(1))
        if "D = 0.75 mm" not in report[0] or "33.3 parcels across" not in report[0] or \
                "= 0.3," not in report[0] or not 0.0 < share < 0.05:
            fail("the parcel report is not the tutorial's (D 0.75 mm, 33.3 across, D/h 0.3, wall share < 0.05)")
        warnings = [l for l in text.splitlines() if l.startswith("parcelflow: warning")]
        if warnings:
            fail("the tutorial bed breaks a parcel rule:\n" + "\n".join(warnings))
        rows = list(csv.DictReader(open(os.path.join(out, "monitors.csv"))))
        last = rows[-1]
        if abs(float(last["time"]) - 0.01) > 1e-9 or float(last["bed_pressure_drop"]) <= 0 or \
                float(last["bed_weight_per_area"]) <= 0:
            fail(f"monitors.csv's last row: {last}")
        print(f"t = {last['time']} s: bed pressure drop {float(last['bed_pressure_drop']):.1f} Pa, "
              f"weight per area {float(last['bed_weight_per_area']):.1f} Pa")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if os.path.exists(work):
        fail(f"the temporary folder {work} is still there")
    print("tutorial_cylinder_smoke: OK")


main()
