#!/usr/bin/env python3
"""Short run of cases/goldschmidt_segregation/coarse_graining.py (issue 14): a third-width slice of the bed
(0.05 m, 16 x 5 x 94 cells, 11,230 beads) fine and in the four coarse-grained variants, settled briefly and
coupled for 0.02 s. The physics of so short a run means nothing; the test checks that the script runs every
variant and writes the table, and that each bed is what it must be, from the parcels the runs wrote:
  fine         11,230 parcels, np 1, dp 1.5 / 2.5 mm
  np8_linear   round(11,230 / 8) parcels of 3 / 5 mm, np 8, dp 1.5 / 2.5 mm
  d5mm_*       round(fine mass / 5 mm parcel mass) parcels of 5 mm, np (5/1.5)^3 and (5/2.5)^3 = 8
  d2.5mm_linear  round(fine mass / 2.5 mm bead mass) parcels of 2.5 mm, np (2.5/1.5)^3 and 1
each class with one np and dp, both classes present, and the solid mass of every coarse bed equal to the fine
bed's within the mass of one of its parcels. np8_linear runs once more with coupling.class_collisions: it must
finish, report its uncorrected cell-steps (none: both classes have l = 2) and move its parcels otherwise than
the run without (the force reaches them). cases/report/mesoscale.py reads the fine and np 8 runs' last
snapshots: finite, non-negative variances. np8_linear_dissipation_l4 runs once
(fix parcel's shear_stress 0.97): the fix reports the parcels' restitution 0.233 with the wall type 3 kept, and
parcelflow's bubbling warning says that shear_stress is on.
The temporary folder is removed at the end.

usage: coarse_graining_smoke.py PARCELFLOW MPIEXEC...
"""
import csv
import math
import os
import re
import shlex
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, copy_case, expect_nothing_left, fail, run  # noqa: E402

SCRIPT = os.path.join(CASES, "goldschmidt_segregation", "coarse_graining.py")
NBEADS, WIDTH, DENSITY = 11230, 0.05, 2526.0
SMALL, LARGE, COARSE = 1.5e-3, 2.5e-3, 5e-3


def mass(d):
    return DENSITY * math.pi / 6 * d ** 3


def edit(case):
    case["liggghts"]["variables"].update({"nbeads": str(NBEADS), "width": str(WIDTH), "settle_steps": "2000"})
    case["mesh"]["lengths"][0] = WIDTH
    case["mesh"]["cells"][0] = 16
    case["output"]["fields_interval"] = 0.0
    case["output"]["monitor_interval"] = 0.0025


def main():
    parcelflow, launcher = sys.argv[1], sys.argv[2:]
    mpirun = list(launcher)
    ranks = mpirun[mpirun.index("-np") + 1]
    del mpirun[mpirun.index("-np"):mpirun.index("-np") + 2]
    here_before = set(os.listdir("."))
    with tempfile.TemporaryDirectory(prefix="pf_coarse_graining_") as work:
        case = copy_case(os.path.join(CASES, "goldschmidt_segregation"), work, edit)
        root = os.path.join(work, "runs")
        stdout = run([sys.executable, SCRIPT, parcelflow, root, "--case", case, "--end", "0.02", "--start", "0.01",
                      "--ranks", ranks, "--mpirun", shlex.join(mpirun)])
        print(stdout)
        if "table written" not in stdout:
            fail("coarse_graining.py wrote no table")
        rows = {r["variant"]: r for r in csv.DictReader(open(os.path.join(root, "coarse_graining.csv")))}
        check(rows)
        check_parcel_reports(root)
        root_cc = os.path.join(work, "runs_class_collisions")
        run([sys.executable, SCRIPT, parcelflow, root_cc, "np8_linear", "--case", case, "--end", "0.02", "--start",
             "0.01", "--ranks", ranks, "--mpirun", shlex.join(mpirun),
             "--set", "coupling.class_collisions={restitution: 0.97, friction: 0.1}"])
        check_class_collisions(os.path.join(root, "np8_linear", "run"), os.path.join(root_cc, "np8_linear", "run"))
        check_mesoscale(os.path.join(root, "fine", "run"), os.path.join(root, "np8_linear", "run"))
        root_ss = os.path.join(work, "runs_shear_stress")
        run([sys.executable, SCRIPT, parcelflow, root_ss, "np8_linear_dissipation_l4", "--case", case, "--end", "0.02",
             "--start", "0.01", "--ranks", ranks, "--mpirun", shlex.join(mpirun)])
        check_shear_stress(os.path.join(root_ss, "np8_linear_dissipation_l4", "run"))
    expect_nothing_left(work, here_before)
    print("PASS")


def check_parcel_reports(root):
    """parcelflow's start-up report on the parcels (coupling/run/parcel_size_report.h), as each run printed it:
    none for single beads; the largest parcel for every coarse bed; the warning of fewer than 6 parcels across
    the 15 mm depth for the 5 mm parcels (3 across) and not for the 2.5 mm ones (6 across); the warning on
    coarse-grained size mixtures for every coarse bed (each stands for the 1.5 and 2.5 mm beads)."""
    expected = {"fine": (None, False), "np8_linear": ("D = 5 mm", True), "d5mm_none": ("D = 5 mm", True),
                "d5mm_linear": ("D = 5 mm", True), "d2.5mm_linear": ("D = 2.5 mm", False)}
    for name, (largest, too_few_across) in expected.items():
        text = open(os.path.join(root, name, "run", "stdout.txt"), errors="replace").read()
        described = "parcelflow: coarse graining: largest parcel" in text
        warned = "rule at least 6 parcels across the narrowest extent between walls: here" in text
        mixture = "for a size mixture whose mixing matters: here" in text and "particles of 1.5 to 2.5 mm" in text
        print(f"[measured] {name}: parcel report {'yes' if described else 'no'}, too-few-across warning "
              f"{'yes' if warned else 'no'}, size-mixture warning {'yes' if mixture else 'no'}")
        if described != (largest is not None) or (largest and f"largest parcel {largest}" not in text):
            fail(f"{name}: the start-up report on the parcels is not what it must be (expected {largest})")
        if warned != too_few_across:
            fail(f"{name}: the warning of too few parcels across the bed is {'there' if warned else 'missing'}")
        if mixture != (largest is not None):
            fail(f"{name}: the warning on a coarse-grained size mixture is {'there' if mixture else 'missing'}")


def check_shear_stress(run_folder):
    text = open(os.path.join(run_folder, "stdout.txt"), errors="replace").read()
    for expected in ("shear_stress: parcel-parcel dampings raised from restitution 0.97 to 0.233238",
                     "the contacts with wall types 3 keep theirs",
                     "for the bubbling and expansion of a size mixture with fix parcel's shear_stress: here l = 2"):
        if expected not in text:
            fail(f"np8_linear_dissipation_l4: '{expected}' is not in its output")
    print("[measured] np8_linear_dissipation_l4: fix parcel's shear_stress 0.97 -> 0.233238, walls kept; warned as on")


def check_class_collisions(without, with_model):
    text = open(os.path.join(with_model, "stdout.txt"), errors="replace").read()
    report = "parcelflow: class collisions (coupling.class_collisions): 0 cell-steps of a pair of classes left " \
             "uncorrected"
    if report not in text:
        fail("the run with coupling.class_collisions lacks its report of 0 uncorrected cell-steps")
    heights = []
    for folder in (without, with_model):
        rows = list(csv.DictReader(open(os.path.join(folder, "monitors.csv"))))
        heights.append((float(rows[-1]["mean_z_type1"]), float(rows[-1]["mean_z_type2"])))
    print(f"[measured] np8_linear mean heights of the classes at the end: {heights[0]} without, {heights[1]} with "
          f"coupling.class_collisions")
    if heights[0] == heights[1]:
        fail("coupling.class_collisions left every parcel where it was without it: no force reached them")


def check_mesoscale(fine, coarse):
    script = os.path.join(CASES, "report", "mesoscale.py")
    out = run([sys.executable, script, fine, coarse, "--start", "0"])
    print(out)
    rows = re.findall(r"^.{40} +\d+((?: +\S+){6})$", out, re.M)
    values = [float(x) for row in rows for x in row.split()]
    if len(rows) != 2 or not all(math.isfinite(x) and x >= 0 for x in values):
        fail(f"mesoscale.py printed {rows}, expected one row of six finite, non-negative values per run")


def check(rows):
    fine_mass = NBEADS / (0.5 / mass(SMALL) + 0.5 / mass(LARGE))  # 50/50 by mass
    expected = {  # parcels, np small, np large, parcel diameters
        "fine": (NBEADS, 1.0, 1.0, SMALL, LARGE),
        "np8_linear": (round(NBEADS / 8), 8.0, 8.0, 2 * SMALL, 2 * LARGE),
        "d5mm_none": (round(fine_mass / mass(COARSE)), (COARSE / SMALL) ** 3, 8.0, COARSE, COARSE),
        "d5mm_linear": (round(fine_mass / mass(COARSE)), (COARSE / SMALL) ** 3, 8.0, COARSE, COARSE),
        "d2.5mm_linear": (round(fine_mass / mass(LARGE)), (LARGE / SMALL) ** 3, 1.0, LARGE, LARGE),
    }
    if set(rows) != set(expected):
        fail(f"table rows {sorted(rows)}, expected {sorted(expected)}")
    measured_fine = float(rows["fine"]["bed_mass_kg"])
    for name, (parcels, np_small, np_large, d_small, d_large) in expected.items():
        r = {k: (v if k in ("variant", "description", "window_s") else float(v)) for k, v in rows[name].items()}
        largest = max(mass(d_small), mass(d_large))
        print(f"[measured] {name}: {r['parcels']:.0f} parcels ({r['parcels_small']:.0f} small, {r['parcels_large']:.0f} "
              f"large; expected {parcels}), np {r['np_small']:.6g} / {r['np_large']:.6g}, dp {r['dp_small_mm']:.6g} / "
              f"{r['dp_large_mm']:.6g} mm, D {r['D_small_mm']:.6g} / {r['D_large_mm']:.6g} mm, bed mass "
              f"{r['bed_mass_kg']:.6g} kg ({(r['bed_mass_kg'] - measured_fine) / largest:+.2f} of its largest parcel "
              f"against the fine bed); DEM step {r['dem_step_s']:.4g} s = {r['steps_per_contact']:.1f} per contact; "
              f"segregation {r['segregation']:.3g}, dp/(W/A) {r['dp_over_weight']:.3g}, run {r['total_wall_s']:.0f} s")
        problems = []
        if r["parcels"] != parcels or r["parcels_small"] + r["parcels_large"] != parcels:
            problems.append(f"{r['parcels']:.0f} parcels, expected {parcels}")
        if min(r["parcels_small"], r["parcels_large"]) < 0.3 * parcels * min(mass(d_small), mass(d_large)) / largest:
            problems.append("a class has too few parcels for 50/50 by mass")
        for what, got, want in (("np small", r["np_small"], np_small), ("np large", r["np_large"], np_large),
                                ("dp small", r["dp_small_mm"], 1e3 * SMALL), ("dp large", r["dp_large_mm"], 1e3 * LARGE),
                                ("D small", r["D_small_mm"], 1e3 * d_small), ("D large", r["D_large_mm"], 1e3 * d_large)):
            if abs(got / want - 1) > 1e-9:
                problems.append(f"{what} {got:.12g}, expected {want:.12g}")
        if r["np_small_spread"] != 0 or r["np_large_spread"] != 0:
            problems.append("a class holds parcels of different np")
        if abs(r["bed_mass_kg"] - measured_fine) > largest:
            problems.append(f"bed mass {r['bed_mass_kg']:.6g} kg differs from the fine {measured_fine:.6g} kg by more "
                            f"than one parcel ({largest:.3g} kg)")
        if abs(r["mass_vs_fine_parcels"] - (r["bed_mass_kg"] - measured_fine) / largest) > 1e-6:
            problems.append(f"mass_vs_fine_parcels {r['mass_vs_fine_parcels']:.6g} disagrees with the masses")
        if not r["steps_per_contact"] >= 10 or not all(math.isfinite(r[k]) for k in (
                "segregation", "rms_small_mm", "rms_large_mm", "dp_over_weight", "loop_wall_s", "total_wall_s")):
            problems.append("a table value is missing")
        if problems:
            fail(f"{name}: " + "; ".join(problems))


if __name__ == "__main__":
    main()
