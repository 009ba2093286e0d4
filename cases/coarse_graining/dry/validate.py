#!/usr/bin/env python3
"""Dry coarse-graining validation (issue 29, part 3): every fine/coarse pair of the silo discharge and the
granular column collapse, and one table of the quantities (README.md in this folder).

Each case is one LIGGGHTS script run twice over: fine with Debian's stock `liggghts` (real particles, no
parcelflow styles) and coarse with `parcelflow dem` (parcels of np 8 and 27 particles, `fix parcel`
scaling none and linear). A run whose folder holds `finished.txt` is not run again, so an interrupted
set continues where it stopped. The table is printed and written to RUNS/coarse_graining_dry.csv.

usage: validate.py [--size smoke|full] [--runs DIR] [--parcelflow PATH] [--liggghts PATH]
                   [--mpirun "mpirun -np 1"] [--only CASE ...] [--seeds N] [--table-only] [--require-pass]
Run it with `nice -n 10` on a shared machine; the runs inherit the niceness.
"""
import argparse
import csv
import math
import os
import shlex
import shutil
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
SCRIPTS = ("silo.in", "column_collapse.in", "granular.in")
DENSITY = 2500.0
TOLERANCE = 0.05  # relative, where the scaling claims to keep the quantity
# The geometric limits of parcels that fix parcel warns of (liggghts_plugins/geometric_limits.h, found from this
# set's runs): an opening narrower than 57 D drains more than 5 % slower than its particles, a body less than
# 12.5 D wide between walls packs looser along them. A row whose geometry is below the limit for its parcels is
# measured and tabulated but not claimed by any scaling: "outside the rule".
OPENING_WIDTH_IN_DIAMETERS = 57.0
BODY_WIDTH_IN_DIAMETERS = 12.5
OUTSIDE_THE_RULE = "outside the rule"
UNCLAIMED = ("not claimed", OUTSIDE_THE_RULE)
DISCHARGED_FROM, DISCHARGED_TO = 0.2, 0.6  # the silo's steady discharge: fractions of the settled mass gone

# (name, np, linear): the fine run and the four coarse variants.
VARIANTS = [("fine", 1, 0), ("np8_none", 8, 0), ("np8_linear", 8, 1), ("np27_none", 27, 0), ("np27_linear", 27, 1)]

# Geometry per size [m, kg, s]. dp = 2 mm; the coarsest parcel (np 27) is D = 6 mm. Full: slots of 6 D and 9 D
# in a silo 16 D wide and 3 D deep (periodic), filled about as high as it is wide; a column 8.3 D wide and
# about twice as high, 3 D deep (periodic).
SIZES = {
    "full": {
        "dp": 0.002,
        "silo": {"silo_width": 0.096, "depth": 0.018, "fill_mass": 0.25, "max_discharge_time": 3.0},
        "orifices": {"silo_narrow": 0.036, "silo_wide": 0.054},
        "column": {"column_width": 0.05, "depth": 0.018, "column_mass": 0.14, "runout_length": 0.4,
                   "collapse_time": 0.6},
    },
    # A few hundred particles per run (seconds): checks that the driver and both codes run, not the physics.
    "smoke": {
        "dp": 0.002,
        "silo": {"silo_width": 0.048, "depth": 0.012, "fill_mass": 0.006, "max_discharge_time": 0.3},
        "orifices": {"silo_narrow": 0.018, "silo_wide": 0.024},
        "column": {"column_width": 0.02, "depth": 0.012, "column_mass": 0.005, "runout_length": 0.1,
                   "collapse_time": 0.1},
    },
}
CASES = ("silo_narrow", "silo_wide", "column")
# Insertion seeds of the realisations beyond the first (the first uses the script's own seed). LIGGGHTS wants
# large primes, different from those of the particle templates and the size distribution.
EXTRA_SEEDS = (67867967, 67867979, 67867999, 67868011, 67868023, 67868041, 67868069, 67868077, 67868111)


def run_settings(size, case):
    """The case's script and its -var settings (without np/linear)."""
    geometry = SIZES[size]
    if case == "column":
        return "column_collapse.in", dict(geometry["column"], dp=geometry["dp"])
    return "silo.in", dict(geometry["silo"], dp=geometry["dp"], orifice=geometry["orifices"][case])


def run_folder(runs, case, variant, realisation):
    """The folder of one run: RUNS/CASE/VARIANT for the first realisation, VARIANT_seedN for the N-th."""
    return os.path.join(runs, case, variant if realisation == 0 else f"{variant}_seed{realisation + 1}")


def run_one(args, folder, case, variant, n_particles, linear, realisation):
    """Runs one variant of one case in `folder` unless it finished before; returns its wall time [s]."""
    finished = os.path.join(folder, "finished.txt")
    if os.path.exists(finished):
        return float(open(finished).read().split()[0])
    if os.path.isdir(folder):
        shutil.rmtree(folder)  # an unfinished run starts again from scratch
    os.makedirs(folder)
    for script in SCRIPTS:
        shutil.copy(os.path.join(HERE, script), folder)
    script, settings = run_settings(args.size, case)
    settings = dict(settings, np=n_particles, linear=linear)
    if realisation > 0:
        settings["insert_seed"] = EXTRA_SEEDS[realisation - 1]
    variables = [word for name, value in settings.items() for word in ("-var", name, str(value))]
    if variant == "fine":
        program = [args.liggghts, "-in", script]
    else:
        program = [args.parcelflow, "dem", script]
    command = shlex.split(args.mpirun) + program + variables
    name = f"{case}/{os.path.basename(folder)}"
    print(f"run {name}: {shlex.join(command)}", flush=True)
    start = time.time()
    with open(os.path.join(folder, "screen.txt"), "w") as screen:
        done = subprocess.run(command, cwd=folder, stdout=screen, stderr=subprocess.STDOUT)
    wall = time.time() - start
    if done.returncode != 0:
        tail = open(os.path.join(folder, "screen.txt"), errors="replace").read()[-3000:]
        sys.exit(f"FAIL: {name} exited with {done.returncode} after {wall:.0f} s "
                 f"(folder {folder}):\n{tail}")
    if "did not settle" in open(os.path.join(folder, "screen.txt"), errors="replace").read():
        sys.exit(f"FAIL: {name}: the packing did not settle (folder {folder}, screen.txt)")
    with open(finished, "w") as f:
        f.write(f"{wall:.1f} s wall\n{shlex.join(command)}\n")
    print(f"  {name}: {wall:.1f} s", flush=True)
    return wall


def run_facts(folder):
    """Spheres and DEM step [s] of a run, from the lines the scripts print."""
    spheres, step = math.nan, math.nan
    for line in open(os.path.join(folder, "screen.txt"), errors="replace"):
        if line.startswith("granular:"):
            step = float(line.split("DEM step")[1].split()[0])
        elif line.startswith(("silo:", "column:")) and "spheres" in line:
            spheres = int(line.split("spheres")[0].split()[-1])
    return spheres, step


def discharge_rate(folder):
    """Steady discharge rate [kg/s]: least-squares slope of the silo mass against time while 20 % to 60 % of
    the settled mass has left (nan if the silo did not get that far); and the settled mass [kg]. Beyond
    60 % the fill is lower than about the wide slot and the rate falls (README.md)."""
    data = np.loadtxt(os.path.join(folder, "discharge.txt"), comments="#", ndmin=2)
    time_s, mass = data[:, 1], data[:, 2]
    initial = mass[0]
    window = (mass <= (1 - DISCHARGED_FROM) * initial) & (mass >= (1 - DISCHARGED_TO) * initial)
    if window.sum() < 3:
        return math.nan, initial
    slope = np.polyfit(time_s[window], mass[window], 1)[0]
    return -slope, initial


def read_spheres(path):
    """x and mass of every sphere of a LIGGGHTS custom dump (id x y z radius mass)."""
    lines = open(path).read().splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS")) + 1
    table = np.array([[float(v) for v in line.split()] for line in lines[start:] if line.strip()])
    return table[:, 1], table[:, 5]


def solid_height(x, mass, at, window, depth):
    """Solid volume per floor area [m] of the spheres with centres in [at - window/2, at + window/2)."""
    inside = (x >= at - window / 2) & (x < at + window / 2)
    return mass[inside].sum() / DENSITY / (window * depth)


def column_quantities(folder, size):
    """Run-out, final height at the back wall and centroid travel of the collapsed column (README.md)."""
    geometry = SIZES[size]
    width, depth, dp = geometry["column"]["column_width"], geometry["column"]["depth"], geometry["dp"]
    x0, m0 = read_spheres(os.path.join(folder, "column_initial.txt"))
    x1, m1 = read_spheres(os.path.join(folder, "column_final.txt"))
    window = 9 * dp  # three of the coarsest parcels wide: coarse deposits are lumped at parcel centres
    # A tenth of the column's solid height: 6.2 mm in the full set, about two layers of the coarsest parcels
    # and five of the fine particles.
    threshold = 0.1 * m0.sum() / DENSITY / (width * depth)
    grid = np.arange(width, geometry["column"]["runout_length"], dp / 4)
    heights = np.array([solid_height(x1, m1, at, window, depth) for at in grid])
    below = np.nonzero(heights < threshold)[0]
    if len(below) == 0 or below[0] == 0:
        front = math.nan
    else:  # linear interpolation between the last grid point above the threshold and the first below
        i = below[0]
        front = grid[i - 1] + (heights[i - 1] - threshold) / (heights[i - 1] - heights[i]) * (grid[i] - grid[i - 1])
    wall_height_0 = solid_height(x0, m0, window / 2, window, depth)
    wall_height_1 = solid_height(x1, m1, window / 2, window, depth)
    centroid_travel = (np.average(x1, weights=m1) - np.average(x0, weights=m0)) / width
    return {"runout": (front - width) / width, "wall_height": wall_height_1 / wall_height_0,
            "centroid_travel": centroid_travel, "mass": m0.sum()}


def beverloo_fit(q_narrow, q_wide, w_narrow, w_wide):
    """Slot Beverloo law Q = (c (W - k d))^(3/2) through two orifices: returns c and k d."""
    a, b = q_narrow ** (2 / 3), q_wide ** (2 / 3)
    c = (b - a) / (w_wide - w_narrow)
    return c, w_narrow - a / c


def mean(values):
    return float(np.mean(values))


def scatter(values):
    """Standard deviation of the realisations relative to their mean [%]; nan for one realisation."""
    return 100 * float(np.std(values, ddof=1)) / abs(mean(values)) if len(values) > 1 else math.nan


def at_least(width, diameters, diameter):
    """Whether `width` is at least `diameters` parcel diameters (D = dp np^(1/3) is rounded off)."""
    return width >= diameters * diameter * (1 - 1e-9)


def claim(variant, quantity_claimed, within_limits=True):
    """Tolerance text of a row: the 5 % where the variant's scaling claims the quantity and the geometry is within
    the limits of the parcels' size; "outside the rule" where only the geometry is not."""
    if not (quantity_claimed and variant.endswith("_linear")):
        return "not claimed"
    return f"{TOLERANCE:.0%}" if within_limits else OUTSIDE_THE_RULE


def compare(fine, coarse, tolerance):
    """(coarse / fine - 1, verdict): "-" where the scaling claims nothing, "no (nan)" where there is no
    difference to judge, else whether it lies within TOLERANCE."""
    difference = (coarse / fine - 1) if fine and math.isfinite(fine) and math.isfinite(coarse) else math.nan
    if tolerance in UNCLAIMED:
        return difference, "-"
    if not math.isfinite(difference):
        return difference, "no (nan)"
    return difference, "yes" if abs(difference) <= TOLERANCE else "no"


def table_rows(results, size):
    """The table: one row per quantity and coarse variant."""
    geometry = SIZES[size]
    dp = geometry["dp"]
    rows = []

    def add(case, quantity, unit, fine_values, variant, coarse_values, claimed, note="", within_limits=True):
        fine, coarse = mean(fine_values), mean(coarse_values)
        tolerance = claim(variant, claimed, within_limits)
        difference, verdict = compare(fine, coarse, tolerance)
        rows.append({"case": case, "quantity": quantity, "unit": unit, "fine": fine, "variant": variant,
                     "coarse": coarse, "difference_percent": 100 * difference, "tolerance": tolerance,
                     "pass": verdict, "realisations": f"{len(fine_values)}/{len(coarse_values)}",
                     "fine_std_percent": scatter(fine_values), "coarse_std_percent": scatter(coarse_values),
                     "note": note})

    widths = geometry["orifices"]
    w_narrow, w_wide = widths["silo_narrow"], widths["silo_wide"]
    silo = {case: results[case] for case in ("silo_narrow", "silo_wide") if case in results}

    def beverloo(variant, diameter):
        """c [kg^(2/3)/(s^(2/3) m)] and k of each realisation of the variant, from its two slots."""
        fits = [beverloo_fit(narrow, wide, w_narrow, w_wide) for narrow, wide in
                zip(silo["silo_narrow"][variant]["rate"], silo["silo_wide"][variant]["rate"])]
        return [c for c, _ in fits], [kd / diameter for _, kd in fits]

    c, k = math.nan, math.nan  # the fine runs' Beverloo law needs both slots
    if len(silo) == 2:
        fine_c, fine_k = beverloo("fine", dp)
        c, k = mean(fine_c), mean(fine_k)
    for name, _, _ in VARIANTS[1:]:
        l = dict((v[0], v[1]) for v in VARIANTS)[name] ** (1 / 3)
        for case, runs in silo.items():
            width = widths[case]
            label = f"discharge rate, slot {1e3 * width:.0f} mm"
            add(case, label, "kg/s", runs["fine"]["rate"], name, runs[name]["rate"], False,
                "Beverloo's empty annulus k D grows with the parcel diameter")
            predicted = (c * (width - k * dp * l)) ** 1.5 if c > 0 and width > k * dp * l else math.nan
            add(case, f"{label} / Beverloo fit of the fine runs at D", "kg/s", [predicted], name,
                runs[name]["rate"], True, f"fine fit: Q = (c (W - k d))^1.5, k = {k:.3g}, d -> D = {1e3 * dp * l:.3g} mm; "
                f"slot {width / (dp * l):.3g} D wide (limit {OPENING_WIDTH_IN_DIAMETERS:g} D)",
                within_limits=at_least(width, OPENING_WIDTH_IN_DIAMETERS, dp * l))
        if len(silo) == 2:
            coarse_c, coarse_k = beverloo(name, dp * l)
            add("silo", "Beverloo c: slope of Q^(2/3) against the slot width", "kg^(2/3)/(s^(2/3) m)", fine_c, name,
                coarse_c, True, "Q^(2/3) = c (W - k D) through both slots, each realisation")
            add("silo", "Beverloo k: empty annulus / sphere diameter", "-", fine_k, name, coarse_k, False,
                "D = dp for the fine runs, the parcel diameter for the coarse: the empty ring at the slot's edge, "
                "the cause of the opening limit; no contact scaling keeps it")
        if "column" in results:
            runs = results["column"]
            width = geometry["column"]["column_width"]
            within = at_least(width, BODY_WIDTH_IN_DIAMETERS, dp * l)
            for key, label in (("runout", "run-out (L - L0)/L0"), ("wall_height", "final height at the wall / initial"),
                               ("centroid_travel", "centroid travel / L0")):
                add("column", label, "-", runs["fine"][key], name, runs[name][key], True,
                    f"column {width / (dp * l):.3g} D wide (limit {BODY_WIDTH_IN_DIAMETERS:g} D)", within)
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--size", choices=sorted(SIZES), default="full")
    parser.add_argument("--runs", help="folder of the runs and the table (default: runs/coarse_graining_dry/SIZE in the repository)")
    parser.add_argument("--parcelflow", default=os.path.join(REPO, "build", "bin", "parcelflow"))
    parser.add_argument("--liggghts", default="liggghts")
    parser.add_argument("--mpirun", default="mpirun -np 1",
                        help="launcher and its flags, one rank (as root: OMPI_ALLOW_RUN_AS_ROOT=1 ...)")
    parser.add_argument("--only", nargs="+", choices=CASES, default=list(CASES), help="run only these cases")
    parser.add_argument("--seeds", type=int, choices=range(1, len(EXTRA_SEEDS) + 2), default=1,
                        help="realisations (insertion seeds) of every fine run; the table holds their means")
    parser.add_argument("--coarse-seeds", type=int, choices=range(1, len(EXTRA_SEEDS) + 2),
                        help="realisations of every coarse run (default: --seeds); they cost seconds each")
    parser.add_argument("--table-only", action="store_true", help="run nothing; tabulate the finished runs")
    parser.add_argument("--require-pass", action="store_true",
                        help="exit with status 1 if a row claimed by its scaling is outside the tolerance")
    args = parser.parse_args()
    coarse_seeds = args.coarse_seeds or args.seeds
    runs = os.path.abspath(args.runs or os.path.join(REPO, "runs", "coarse_graining_dry", args.size))
    os.makedirs(runs, exist_ok=True)

    results, timings = {}, []  # results[case][variant]: {quantity: [value of each realisation]}
    for case in args.only:
        results[case] = {}
        for realisation in range(max(args.seeds, coarse_seeds)):
            for variant, n_particles, linear in VARIANTS:
                if realisation >= (args.seeds if variant == "fine" else coarse_seeds):
                    continue
                folder = run_folder(runs, case, variant, realisation)
                if args.table_only and not os.path.exists(os.path.join(folder, "finished.txt")):
                    continue
                wall = run_one(args, folder, case, variant, n_particles, linear, realisation)
                if case == "column":
                    quantities = column_quantities(folder, args.size)
                else:
                    rate, mass = discharge_rate(folder)
                    quantities = {"rate": rate, "mass": mass}
                for name, value in quantities.items():
                    results[case].setdefault(variant, {}).setdefault(name, []).append(value)
                timings.append((case, os.path.basename(folder), wall, quantities["mass"]) + run_facts(folder))
        if any(variant not in results[case] for variant, _, _ in VARIANTS):
            results.pop(case)  # tabulated only when every variant has run

    rows = table_rows(results, args.size)
    table = os.path.join(runs, "coarse_graining_dry.csv")
    with open(table, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]) if rows else ["case"])
        writer.writeheader()
        writer.writerows(rows)
    print(f"\n{'quantity':62s} {'fine':>10s} {'variant':12s} {'coarse':>10s} {'diff %':>8s} {'tolerance':>11s} "
          f"{'pass':5s} {'runs':5s} std % (fine/coarse)")
    for r in rows:
        print(f"{r['quantity']:62s} {r['fine']:10.4g} {r['variant']:12s} {r['coarse']:10.4g} "
              f"{r['difference_percent']:8.2f} {r['tolerance']:>11s} {r['pass']:5s} {r['realisations']:5s} "
              f"{r['fine_std_percent']:.2g} / {r['coarse_std_percent']:.2g}")
    print("\nrun times (wall, this machine):")
    for case, variant, wall, mass, spheres, step in timings:
        print(f"  {case:12s} {variant:18s} {wall:8.1f} s   {spheres:6d} spheres, {mass:.6g} kg, DEM step {step:.3g} s")
    print(f"\ntable written: {table} ({len(rows)} rows)")
    failed = [r for r in rows if r["pass"].startswith("no")]
    outside = [r for r in rows if r["tolerance"] == OUTSIDE_THE_RULE]
    print(f"{len(failed)} of {sum(r['tolerance'] not in UNCLAIMED for r in rows)} claimed rows outside the tolerance; "
          f"{len(outside)} rows of a scaling's quantity outside the parcels' geometric limits, not claimed: "
          + ", ".join(f"{r['case']} {r['variant']} {r['difference_percent']:+.1f} %" for r in outside))
    if args.require_pass and failed:
        sys.exit(1)


if __name__ == "__main__":
    main()
