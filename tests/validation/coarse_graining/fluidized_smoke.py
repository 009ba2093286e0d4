#!/usr/bin/env python3
"""Smoke test of cases/coarse_graining/fluidized/validate.py (issue 29 part 3): the driver at --size smoke (a
20 mm bed of 800 beads, 0.3 s per variant, about 1.5 min on 1 core). The physics of so small a bed means
nothing; the test checks that
  * the driver ran the fine bed and the three coarse variants and wrote the table with every row (3 variants
    x 6 quantities), the fine bed's U_mf, dp/(W/A), expansion, void share and rms numbers, and the diagnostics
    (voids counted, their width, emulsion gas fraction, the solids' motion) for every variant;
  * --record wrote one row per variant into a run record, a second call with the fine bed alone (finished, not
    run again) replaced its row instead of adding one, and report.py drew the bed's table from the record;
  * each coarse run had its parcels (np 8, np 27, 5 mm parcels of both classes) and the fine bed's solid mass
    to within one of its largest parcels;
  * the inlet ramped (the bed's case.yaml has the ramp) and the fine bed's pressure drop rose with it;
  * variants not starting with a fine bed are refused before any run (exit 2);
  * the temporary folder is removed and nothing is left in the working folder.

usage: fluidized_smoke.py PARCELFLOW MPIEXEC... -np N
"""
import csv
import math
import os
import shlex
import subprocess
import sys
import tempfile

import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, expect_nothing_left, fail, run  # noqa: E402

DRIVER = os.path.join(CASES, "coarse_graining", "fluidized", "validate.py")
PARCELS = {"fine": (1, 1, 1.5, 2.5), "np8_linear": (8, 8, 3.0, 5.0), "np27_linear": (27, 27, 4.5, 7.5),
           "d5mm_linear": (37.04, 8, 5.0, 5.0)}  # np small, np large, D small, D large [mm]
QUANTITIES = ("u_mf", "dp_over_weight", "expansion", "void_share", "dp_rms_over_weight", "height_rms_mm")
DIAGNOSTICS = ("bubbles_per_slice", "emulsion_gas_fraction", "solids_motion_z_cm2s2")
REPORT = os.path.join(CASES, "coarse_graining", "fluidized", "report.py")


def main():
    parcelflow, mpirun = sys.argv[1], sys.argv[2:]
    ranks = mpirun[mpirun.index("-np") + 1]
    del mpirun[mpirun.index("-np"):mpirun.index("-np") + 2]  # coarse_graining.py appends its own
    here_before = set(os.listdir("."))
    with tempfile.TemporaryDirectory(prefix="pf_cg_fluidized_") as work:
        check_refused(parcelflow, work)
        record = os.path.join(work, "record", "runs.csv")
        stdout = run([sys.executable, DRIVER, parcelflow, "--size", "smoke", "--runs", work, "--ranks", ranks,
                      "--mpirun", shlex.join(mpirun), "--record", record], timeout=900)
        print(stdout)
        if "table written" not in stdout:
            fail("validate.py wrote no table")
        check_table(os.path.join(work, "coarse_graining_fluidized.csv"))
        check_diagnostics(stdout)
        check_beds(os.path.join(work, "coarse_graining.csv"))
        check_ramp(work)
        check_record(parcelflow, work, ranks, mpirun, record)
    expect_nothing_left(work, here_before)
    print("PASS")


def check_refused(parcelflow, work):
    """Variants that cannot make a table are refused with exit 2, naming the key, before any run."""
    for variants, what in ((["np8_linear", "fine"], "must be a fine bed"),):
        runs = os.path.join(work, "refused")
        result = subprocess.run([sys.executable, DRIVER, parcelflow, "--size", "smoke", "--runs", runs,
                                 "--variants", *variants], capture_output=True, text=True, timeout=60)
        if result.returncode != 2 or "--variants" not in result.stderr or what not in result.stderr:
            fail(f"--variants {' '.join(variants)}: exit {result.returncode}, stderr {result.stderr!r}; "
                 f"expected exit 2 naming --variants and '{what}'")
        if os.path.exists(runs):
            fail(f"--variants {' '.join(variants)}: refused, but made {runs}")


def check_record(parcelflow, work, ranks, mpirun, record):
    """A row per variant; the fine bed alone measured again replaces its row; report.py draws the table."""
    rows = list(csv.DictReader(open(record)))
    if sorted(r["variant"] for r in rows) != sorted(PARCELS):
        fail(f"record: variants {[r['variant'] for r in rows]}, expected {sorted(PARCELS)}")
    stdout = run([sys.executable, DRIVER, parcelflow, "--size", "smoke", "--runs", work, "--ranks", ranks,
                  "--mpirun", shlex.join(mpirun), "--record", record, "--variants", "fine"], timeout=300)
    if "fine: finished before, not run again" not in stdout or "expansion" not in stdout:
        fail(f"the fine bed alone: expected it measured without a new run, got:\n{stdout}")
    again = list(csv.DictReader(open(record)))
    if len(again) != len(rows):
        fail(f"record: {len(again)} rows after measuring the fine bed again, expected {len(rows)}")
    table = run([sys.executable, REPORT, record], timeout=60)
    print(table)
    header = next((line for line in table.splitlines() if line.startswith("| quantity | fine |")), "")
    if not all(v in header for v in PARCELS if v != "fine") or "| u_mf [m/s] |" not in table:
        fail(f"report.py: no table with every variant:\n{table}")


def check_diagnostics(stdout):
    """Every diagnostic line printed with a finite value per variant."""
    lines = {line.split()[0]: line.split()[1:] for line in stdout.splitlines() if line.strip()}
    for name in DIAGNOSTICS:
        values = [float(v) for v in lines.get(name, [])[:len(PARCELS)]]
        if len(values) != len(PARCELS) or not all(math.isfinite(v) for v in values):
            fail(f"diagnostic {name}: {lines.get(name)}, expected a finite value for each of {list(PARCELS)}")


def check_table(path):
    rows = list(csv.DictReader(open(path)))
    for variant in PARCELS:
        if variant == "fine":
            continue
        names = [r["quantity"] for r in rows if r["variant"] == variant]
        if names != list(QUANTITIES):
            fail(f"table: rows {names} for {variant}, expected {list(QUANTITIES)}")
    if len(rows) != 3 * len(QUANTITIES):
        fail(f"table: {len(rows)} rows, expected {3 * len(QUANTITIES)}")
    for r in rows:
        if r["quantity"] in ("u_mf", "dp_over_weight", "expansion") and not math.isfinite(float(r["fine"])):
            fail(f"table: no fine value in row {r}")
        if r["pass"] not in ("True", "False"):
            fail(f"table: pass {r['pass']!r} in row {r}")


def check_beds(path):
    beds = {r["variant"]: r for r in csv.DictReader(open(path))}
    for variant, (np_small, np_large, d_small, d_large) in PARCELS.items():
        bed = beds.get(variant)
        if bed is None:
            fail(f"coarse_graining.csv has no row of {variant}")
        for key, expected in (("np_small", np_small), ("np_large", np_large), ("D_small_mm", d_small),
                              ("D_large_mm", d_large)):
            if abs(float(bed[key]) / expected - 1) > 1e-3:
                fail(f"{variant}: {key} {bed[key]}, expected {expected}")
        if abs(float(bed["mass_vs_fine_parcels"])) > 1.0:
            fail(f"{variant}: solid mass differs from the fine bed's by {bed['mass_vs_fine_parcels']} parcels")


def check_ramp(work):
    inlet = yaml.safe_load(open(os.path.join(work, "bed", "case.yaml")))["boundaries"]["zmin"]
    if not inlet.get("ramp_time", 0) > 0:
        fail(f"the bed's inlet has no ramp: {inlet}")
    rows = list(csv.DictReader(open(os.path.join(work, "fine", "run", "monitors.csv"))))
    dp = [float(r["bed_pressure_drop"]) for r in rows]
    early, late = sum(dp[1:6]) / 5, sum(dp[-5:]) / 5
    if not late > 2 * early > 0:
        fail(f"the fine bed's pressure drop did not rise with the inlet: {early:.4g} Pa early, {late:.4g} Pa late")


if __name__ == "__main__":
    main()
