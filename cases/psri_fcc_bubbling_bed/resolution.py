#!/usr/bin/python3
"""Is the filtered drag's bed surface a property of the model or of the resolution? (issue 32)

The reduced case (reduced/case.yaml) with `RadlSundaresanFilteredBVK`, run 30 s with time averages over 20-30 s,
and five variants that each change one thing:
  baseline     the reduced case with the filtered drag (75 mm cells cut by the column's cylinders, 30 mm
               parcels, central return region)
  mesh_50mm    gas cells of 50 mm (18 x 18 x 150; the filter width follows the cell, as the model defines it)
  filter_2x    the filter width twice the cell (coupling.filtered_drag.filter_cells 2) on the 75 mm cells
  parcels_24mm parcels of 24 mm (131,836: the same solids volume), spring 8,000 N/m (scaled with the diameter
               as the reduced case scaled the full case's 5,000 N/m at 15 mm), DEM step 2e-4 s (the contact time
               scales with D), skin and reinjection interval likewise
  wall_return  the return region at the wall, 0.35 < r < 0.44 m (a dipleg-like annulus) instead of r < 0.2 m
  staircase    whole cells selected by their centre instead of cut cells (the staircase column of the cases
               before issue 31; the box's side patches get their wall entries back)
Each runs in RUNS/VARIANT/run on --ranks ranks with checkpoints every 5 s; calling the script again continues
an unfinished run from its last checkpoint and skips a finished one, so the set can be spread over sessions.
`--summary` only tabulates what has finished (RUNS/resolution.csv) and plots every dp/(g dz) profile with the
experiment's 3.5 m (RUNS/resolution_profiles.png).

The table and the plot take the variants not finished in RUNS from the record in resolution/ (table.csv and
profiles.csv, each row with the date it was recorded and the commit of the checkout the script ran from, which
should be the binary's); `--summary --record` writes the finished runs there, so
that a study spread over sessions on machines that do not keep their runs can still be drawn whole.

usage: resolution.py PARCELFLOW RUNS [VARIANT ...] [--ranks N] [--mpirun CMD] [--end T] [--summary [--record]]
"""
import argparse
import csv
import datetime
import glob
import math
import os
import re
import shlex
import shutil
import subprocess
import sys

import h5py
import numpy as np
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
SPARGER_Z = 0.34                # the reduced case's sparger layer [m]
EXPERIMENT_SURFACE = 3.5        # above the sparger [m]
ZONES = ((0.4, 1.5), (1.5, 2.5), (2.5, 3.5), (3.5, 4.5))
AVERAGE_FROM = 20.0
RECORD = os.path.join(HERE, "resolution")  # the runs' rows and profiles, kept with the case: machines do not keep runs


def filtered(case):
    case["coupling"]["drag"] = "RadlSundaresanFilteredBVK"
    case["coupling"]["filtered_drag"] = {"particle_density": 1500}
    case["monitors"]["average"] = {"start": AVERAGE_FROM}
    # The study's first runs (baseline, mesh_50mm, 2026-12-05) solved with the strict criterion, the default
    # then: every variant keeps it, so that each differs from the baseline in one thing only.
    case["solver"] = {"pressure": {"criterion": "strict"}, "momentum": {"criterion": "strict"}}


def mesh_50mm(case):
    case["mesh"]["cells"] = [18, 18, 150]
    case["mesh"]["lengths"] = [0.9, 0.9, 7.5]  # z faces at multiples of 50 mm: the column top 7.0 m is one


def filter_2x(case):
    case["coupling"]["filtered_drag"]["filter_cells"] = 2


def parcels_24mm(case):
    v = case["liggghts"]["variables"]
    scale = 24.0 / 30.0
    v.update(D="0.024", kn=str(round(10000 * scale)), nparcels=str(round(67500 / scale ** 3)),
             skin=repr(round(0.006 * scale, 6)), settle_steps=str(round(12000 / scale)),
             relax_steps=str(round(2000 / scale)), reinject_every=str(round(8 / scale)))
    case["time"]["dem_step"] = 2.5e-4 * scale


def wall_return(case):
    case["liggghts"]["variables"].update(return_r="0.44", return_rin="0.35")


def staircase(case):
    case["mesh"]["walls"] = "staircase"
    for side in ("xmin", "xmax", "ymin", "ymax"):
        case["boundaries"][side] = {"type": "wall"}


VARIANTS = {"baseline": [], "mesh_50mm": [mesh_50mm], "filter_2x": [filter_2x], "parcels_24mm": [parcels_24mm],
            "wall_return": [wall_return], "staircase": [staircase]}


def prepare(root, name, end):
    """RUNS/NAME/case (a copy of reduced/ with the variant's edits) and RUNS/NAME/fcc_bed.in beside it."""
    folder = os.path.join(root, name)
    case = os.path.join(folder, "case")
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(os.path.join(HERE, "reduced"), case, ignore=shutil.ignore_patterns("output"))
    shutil.copy(os.path.join(HERE, "fcc_bed.in"), os.path.join(folder, "fcc_bed.in"))
    config = yaml.safe_load(open(os.path.join(case, "case.yaml")))
    config["time"]["end"] = end
    filtered(config)
    for edit in VARIANTS[name]:
        edit(config)
    with open(os.path.join(case, "case.yaml"), "w") as f:
        yaml.safe_dump(config, f, sort_keys=False)
    return case


def finished(run):
    try:
        return "parcelflow: done:" in open(os.path.join(run, "stdout.txt"), errors="replace").read()
    except OSError:
        return False


def last_checkpoint(run):
    steps = sorted(glob.glob(os.path.join(run, "checkpoints", "step_[0-9]*")))
    return steps[-1] if steps else None


def run_variant(args, name):
    run = os.path.join(args.runs, name, "run")
    if finished(run):
        print(f"{name}: finished before", flush=True)
        return
    checkpoint = last_checkpoint(run)
    case = os.path.join(args.runs, name, "case")
    if checkpoint is None or not os.path.isdir(case):
        case = prepare(args.runs, name, args.end)  # a continued run keeps its case folder unchanged
    command = shlex.split(args.mpirun) + ["-np", str(args.ranks), args.parcelflow, "run", case, "--output", run]
    if checkpoint:
        command += ["--restart", checkpoint]
    print(f"{name}: {'continues ' + checkpoint if checkpoint else 'starts'}", flush=True)
    os.makedirs(run, exist_ok=True)
    with open(os.path.join(run, "stdout.txt"), "a") as out:
        code = subprocess.call(command, stdout=out, stderr=subprocess.STDOUT)
    print(f"{name}: exit {code}", flush=True)


def profile(run):
    """(interval mid-heights, dp/(g dz)) of averages.csv, and its header's averaged time span."""
    lines = open(os.path.join(run, "averages.csv")).read().splitlines()
    span = re.search(r"time averages over ([0-9.e+-]+) s", lines[0])
    rows = [r for r in csv.DictReader(lines[1:]) if r.get("interval_mid_z")]
    return (np.array([float(r["interval_mid_z"]) for r in rows]), np.array([float(r["dp_over_g_dz"]) for r in rows]),
            float(span.group(1)) if span else math.nan)


def surface(mid, rho):
    """The first height above the dense zone where dp/(g dz) falls below half its 0.6-1.5 m median (README)."""
    half = 0.5 * np.median(rho[(mid >= 0.6) & (mid <= 1.5)])
    for k in range(1, len(mid)):
        if mid[k] > 1.5 and rho[k] < half <= rho[k - 1]:
            return mid[k - 1] + (half - rho[k - 1]) * (mid[k] - mid[k - 1]) / (rho[k] - rho[k - 1])
    return math.nan


def zone_solids(run):
    """Mean of the cells' time-averaged solids fraction per height zone (last averages snapshot), weighted by
    the cells' fluid volume: a cut cell's fluid fraction (all 1 on a staircase mesh, which writes none)."""
    last = sorted(glob.glob(os.path.join(run, "averages_[0-9]*.h5")))[-1]
    with h5py.File(os.path.join(run, "fields_mesh.h5"), "r") as f:
        z = np.asarray(f["points"]).reshape(-1, 8, 3).mean(axis=1)[:, 2]
        fluid = np.asarray(f["fluid_fraction"]).ravel() if "fluid_fraction" in f else np.ones_like(z)
    with h5py.File(last, "r") as f:
        solids = np.asarray(f["mean_solids_fraction"]).ravel()
    return [float(np.average(solids[(z >= lo) & (z < hi)], weights=fluid[(z >= lo) & (z < hi)])) for lo, hi in ZONES]


def summarize(name, run):
    mid, rho, span = profile(run)
    rows = list(csv.DictReader(open(os.path.join(run, "monitors.csv"))))
    window = [r for r in rows if float(r["time"]) >= AVERAGE_FROM]
    mean = lambda key: float(np.mean([float(r[key]) for r in window]))  # noqa: E731
    last = rows[-1]
    stdout = open(os.path.join(run, "stdout.txt"), errors="replace").read()
    walls = [float(w) for w in re.findall(r"parcelflow: done: .* in ([0-9.]+) s wall", stdout)]
    row = {"variant": name, "averaged_s": span, "surface_above_sparger_m": surface(mid, rho) - SPARGER_Z}
    for (lo, hi), value in zip(ZONES, zone_solids(run)):
        row[f"solids_{lo:g}-{hi:g}m"] = value
    row.update({"mean_height_m": mean("mean_z_type1"), "dp_over_weight": mean("bed_pressure_drop") /
                mean("bed_weight_per_area"), "out": float(last.get("reinjected_out_total", "nan")),
                "in": float(last.get("reinjected_in_total", "nan")),
                "pending": float(last.get("reinjection_pending", "nan")), "lost": float(last["lost_parcels"]),
                "loop_wall_s": sum(walls) if walls else math.nan})
    return row, (mid, rho)


def read_record():
    """The recorded table rows {variant: row} and profiles {variant: (mid, rho)} of RECORD (empty without it)."""
    table, profiles = {}, {}
    if os.path.exists(os.path.join(RECORD, "table.csv")):
        with open(os.path.join(RECORD, "table.csv")) as f:
            for row in csv.DictReader(f):
                table[row["variant"]] = {k: v if k in ("variant", "recorded", "commit") else float(v)
                                         for k, v in row.items()}
        points = {}
        with open(os.path.join(RECORD, "profiles.csv")) as f:
            for row in csv.DictReader(f):
                points.setdefault(row["variant"], []).append((float(row["z"]), float(row["dp_over_g_dz"])))
        profiles = {name: tuple(np.array(c) for c in zip(*rows)) for name, rows in points.items()}
    return table, profiles


def source_commit():
    """The commit of the checkout this script is in (the binary is expected to be built from it)."""
    try:
        return subprocess.run(["git", "-C", HERE, "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                              check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def write_record(table, profiles):
    """RECORD/table.csv and profiles.csv: the finished runs replace their variant's recorded rows."""
    recorded_table, recorded_profiles = read_record()
    today = datetime.date.today().isoformat()
    commit = source_commit()
    for row in table:
        recorded_table[row["variant"]] = dict(row, recorded=today, commit=commit)
        recorded_profiles[row["variant"]] = profiles[row["variant"]]
    os.makedirs(RECORD, exist_ok=True)
    rows = [recorded_table[name] for name in VARIANTS if name in recorded_table]
    with open(os.path.join(RECORD, "table.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    with open(os.path.join(RECORD, "profiles.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["variant", "z", "dp_over_g_dz"])
        for name in VARIANTS:
            if name in recorded_profiles:
                writer.writerows((name, f"{z:.6g}", f"{r:.6g}") for z, r in zip(*recorded_profiles[name]))
    print(f"recorded in {RECORD}")


def report(args):
    """The table and the profiles of the finished runs in RUNS and, for the variants not finished there, of the
    record (labelled with its date)."""
    table, profiles = [], {}
    for name in VARIANTS:
        run = os.path.join(args.runs, name, "run")
        if finished(run):
            row, profiles[name] = summarize(name, run)
            table.append(dict(row, recorded="this run", commit=source_commit()))
    if args.record and table:
        write_record([{k: v for k, v in row.items() if k != "recorded"} for row in table], profiles)
    recorded_table, recorded_profiles = read_record()
    for name in VARIANTS:
        if name not in profiles and name in recorded_table:
            table.append(recorded_table[name])
            profiles[name] = recorded_profiles[name]
    if not table:
        sys.exit("no finished variant to tabulate and none recorded")
    table.sort(key=lambda row: list(VARIANTS).index(row["variant"]))
    path = os.path.join(args.runs, "resolution.csv")
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(table[0]))
        writer.writeheader()
        writer.writerows(table)
    for key in table[0]:
        print(f"{key:26s}" + "".join(f"{r[key]:>14.4g}" if isinstance(r[key], float) else f"{r[key]:>14s}"
                                     for r in table))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5, 7))
    for row in table:
        mid, rho = profiles[row["variant"]]
        label = row["variant"] if row["recorded"] == "this run" else f"{row['variant']} ({row['recorded']})"
        ax.plot(rho, mid, "o-", ms=2, label=label)
    ax.axhline(SPARGER_Z + EXPERIMENT_SURFACE, color="k", ls="--", lw=0.8, label="experiment's surface")
    ax.set_xlabel("dp / (g dz) [kg/m3]")
    ax.set_ylabel("height z [m]")
    ax.legend(fontsize=8)
    ax.set_title(f"filtered drag, averages over {AVERAGE_FROM:g}-{args.end:g} s")
    fig.tight_layout()
    fig.savefig(os.path.join(args.runs, "resolution_profiles.png"), dpi=120)
    print(f"table: {path}; profiles: {os.path.join(args.runs, 'resolution_profiles.png')}")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("parcelflow")
    p.add_argument("runs")
    p.add_argument("variants", nargs="*")
    p.add_argument("--ranks", type=int, default=2)
    p.add_argument("--mpirun", default="mpirun")
    p.add_argument("--end", type=float, default=30.0)
    p.add_argument("--summary", action="store_true")
    p.add_argument("--record", action="store_true",
                   help="keep the finished runs' rows and profiles in the case's resolution/ folder")
    args = p.parse_intermixed_args()
    args.runs = os.path.abspath(args.runs)
    args.parcelflow = os.path.abspath(args.parcelflow)
    unknown = [v for v in args.variants if v not in VARIANTS]
    if unknown:
        sys.exit(f"unknown variant(s) {unknown}; known: {', '.join(VARIANTS)}")
    if not args.summary:
        for name in args.variants or VARIANTS:
            run_variant(args, name)
    report(args)


if __name__ == "__main__":
    main()
