#!/usr/bin/python3
"""Controlled runs of the Goldschmidt bed (issue 14): the shipped case and variants that each change one
setting, run for the same coupled time, tabulated with the void measure (void_shape.py), the segregation,
dp/(W/A), the gas-fraction-floor hits and the cost.

Usage: controlled_runs.py PARCELFLOW OUTPUT_ROOT [--ranks N] [--end T] [--start S] [--jobs J] [VARIANT ...]
  Each variant runs in OUTPUT_ROOT/VARIANT/ (case copy in case/, run in run/); a variant whose run/
  already has a finished summary is not rerun, so the script can be called again to add variants or to
  rebuild the table. Statistics are taken over coupled times >= S (default 0.3 s: after the start-up).
  Without VARIANT names: all of them. --jobs runs that many variants at once (each with --ranks ranks).
"""
import argparse
import copy
import csv
import os
import shutil
import subprocess
import sys
import time

import numpy as np
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import run_lock  # noqa: E402
import void_shape  # noqa: E402

# name: (what changes, case.yaml changes {dotted.key: value}, LIGGGHTS script variables {name: value})
VARIANTS = {
    "shipped": ("the case as shipped", {}, {}),
    "depth_1_cell": ("1 gas cell across the 15 mm depth instead of 5", {"mesh.cells": [47, 1, 94]}, {}),
    "free_slip_front_back": ("front and back walls free-slip for the gas",
                             {"boundaries.ymin": {"type": "wall", "slip": "free_slip"},
                              "boundaries.ymax": {"type": "wall", "slip": "free_slip"}}, {}),
    "no_wall_friction": ("bead-wall friction 0 instead of 0.09", {}, {"wall_friction": "0.0"}),
    "gidaspow": ("Gidaspow drag instead of Wen-Yu", {"coupling.drag": "Gidaspow"}, {}),
    "beetstra": ("Beetstra (BVK) drag instead of Wen-Yu", {"coupling.drag": "BeetstraVanDerHoefKuipers"}, {}),
    "column_0.7m": ("the experiment's 0.7 m column with the same 94 cells over its height (3.2 x 3.0 x 7.4 mm cells: "
                    "the mesh shipped before 2026-12-03) instead of 0.3 m (cubic 3.2 mm cells)",
                    {"mesh.lengths": [0.15, 0.015, 0.7]}, {"height": "0.7"}),
    "column_0.7m_188": ("the 0.7 m column with 188 gas cells over the height (3.7 mm)",
                        {"mesh.lengths": [0.15, 0.015, 0.7], "mesh.cells": [47, 5, 188]}, {"height": "0.7"}),
    "column_0.7m_219": ("the 0.7 m column with 219 gas cells over the height (cubic 3.2 mm cells, as in the 0.3 m "
                        "column)", {"mesh.lengths": [0.15, 0.015, 0.7], "mesh.cells": [47, 5, 219]}, {"height": "0.7"}),
    "velocity_0.8": ("inlet 0.8 m/s instead of 1.1: the settled bed (a_g 0.37, denser than the experiment's) has a "
                     "lower U_mf, so this keeps about the experiment's U/U_mf",
                     {"boundaries.zmin": {"type": "velocity_inlet", "superficial_velocity": [0, 0, 0.8]}}, {}),
    "centroid": ("centroid kernel instead of Gaussian", {"coupling.kernel": {"type": "centroid"}}, {}),
    "kernel_cell_axes": ("Gaussian h = the cell length per axis (the only kernel before 2026-12-02; on the cubic cells "
                         "of the 0.3 m column 3.2 / 3.0 / 3.2 mm) instead of the cube root of the cell volume (3.13 mm)",
                         {"coupling.kernel": {"type": "gaussian", "sharpness": 1.0, "radius": 2,
                                              "length_scale": "cell_axes"}}, {}),
    "kernel_wide": ("Gaussian sharpness 0.5 (wider)",
                    {"coupling.kernel": {"type": "gaussian", "sharpness": 0.5, "radius": 2}}, {}),
    "kernel_narrow": ("Gaussian sharpness 2, radius 1 (narrower)",
                      {"coupling.kernel": {"type": "gaussian", "sharpness": 2.0, "radius": 1}}, {}),
    "floor_0.2": ("gas-fraction floor 0.2 instead of 0.3", {"coupling.gas_fraction_floor": 0.2}, {}),
    "distributor": ("porous-plate inlet with a pressure drop of 300 Pa (0.28 of the bed weight) instead of a fixed "
                    "velocity on every face",
                    {"boundaries.zmin": {"type": "velocity_inlet", "superficial_velocity": [0, 0, 1.1],
                                         "distributor_pressure_drop": 300.0}}, {}),
    "startup_ramp": ("inlet velocity ramped from 0 over 0.2 s instead of full flow at once",
                     {"boundaries.zmin": {"type": "velocity_inlet", "superficial_velocity": [0, 0, 1.1],
                                          "ramp_time": 0.2}}, {}),
    "restitution_0.9": ("restitution 0.9 instead of 0.97 for every pair (damping x 3.4573)", {},
                        {"damping": "448.721 349.888 317.293 349.888 208.547 147.464 317.293 147.464 147.464"}),
    "bead_friction_0.3": ("bead-bead friction 0.3 instead of 0.10", {}, {"bead_friction": "0.30"}),
    "kick": ("left third of the settled bed kicked upwards at 0.3 m/s", {}, {"kick_vz": "0.3"}),
}


def set_key(tree, dotted, value):
    keys = dotted.split(".")
    for k in keys[:-1]:
        tree = tree.setdefault(k, {})
    tree[keys[-1]] = copy.deepcopy(value)


def prepare(name, root):
    _, changes, variables = VARIANTS[name]
    case = os.path.join(root, name, "case")
    shutil.rmtree(case, ignore_errors=True)
    os.makedirs(case)
    shutil.copy(os.path.join(HERE, "goldschmidt.in"), case)
    config = yaml.safe_load(open(os.path.join(HERE, "case.yaml")))
    for key, value in changes.items():
        set_key(config, key, value)
    config["liggghts"]["variables"].update(variables)
    config["output"]["fields_interval"] = 0.02  # 50 snapshots per second for the void measure
    with open(os.path.join(case, "case.yaml"), "w") as f:
        yaml.safe_dump(config, f, sort_keys=False)
    return case


def finished(run):
    log = os.path.join(run, "stdout.txt")
    return os.path.exists(log) and "parcelflow: done:" in open(log, errors="replace").read()


def start(name, args):
    case = prepare(name, args.root)
    run = os.path.join(args.root, name, "run")
    shutil.rmtree(run, ignore_errors=True)
    os.makedirs(run)
    out = open(os.path.join(run, "stdout.txt"), "w")
    command = ["mpirun", "-np", str(args.ranks), args.parcelflow, "run", case, "--output", run,
               "--end", str(args.end)]
    return subprocess.Popen(command, stdout=out, stderr=subprocess.STDOUT), time.time()


def summarize(name, args):
    run = os.path.join(args.root, name, "run")
    rows = list(csv.DictReader(open(os.path.join(run, "monitors.csv"))))
    t = np.array([float(r["time"]) for r in rows])
    w = t >= args.start
    col = lambda key: np.array([float(r[key]) for r in rows])[w]  # noqa: E731
    small, large = col("mean_z_type1"), col("mean_z_type2")
    h = 0.5 * (small.mean() + large.mean())
    measure = void_shape.run_measure(void_shape.read_run(run, args.start))
    wall = open(os.path.join(run, "stdout.txt"), errors="replace").read()
    return {
        "variant": name, "change": VARIANTS[name][0],
        "layer_share": measure["layer_share"], "bubbles": measure["bubbles_per_snapshot"],
        "bubble_width_mm": 1000 * measure["mean_bubble_width"], "lateral_spread": measure["lateral_spread"],
        "segregation": (small.mean() - large.mean()) / h,
        "dp_over_weight": col("bed_pressure_drop").mean() / col("bed_weight_per_area").mean(),
        "dp_rms_over_weight": col("bed_pressure_drop").std() / col("bed_weight_per_area").mean(),
        "floor_hits": float(rows[-1]["floor_hits"]),
        "wall_s": wall_seconds(wall),
    }


def wall_seconds(stdout):
    """The wall time of the summary line 'parcelflow: done: N gas steps, T s simulated in W s wall; ...'."""
    for line in reversed(stdout.splitlines()):
        if line.startswith("parcelflow: done:") and " s wall" in line:
            return float(line.split(" s wall")[0].split()[-1])
    return float("nan")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("parcelflow")
    p.add_argument("root")
    p.add_argument("variants", nargs="*")
    p.add_argument("--ranks", type=int, default=1)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--end", type=float, default=1.0)
    p.add_argument("--start", type=float, default=0.3)
    args = p.parse_intermixed_args()  # variants may come after the options
    names = args.variants or list(VARIANTS)
    unknown = [n for n in names if n not in VARIANTS]
    if unknown:
        sys.exit(f"unknown variant(s) {unknown}; known: {', '.join(VARIANTS)}")
    run_lock.refuse_if_writing([os.path.join(args.root, n, "run") for n in names])
    todo = [n for n in names if not finished(os.path.join(args.root, n, "run"))]
    running = {}
    while todo or running:
        while todo and len(running) < args.jobs:
            name = todo.pop(0)
            running[name] = start(name, args)
            print(f"started {name}", flush=True)
        time.sleep(5)
        for name, (proc, t0) in list(running.items()):
            if proc.poll() is not None:
                print(f"{name}: exit {proc.returncode} after {time.time() - t0:.0f} s", flush=True)
                del running[name]
    table = [summarize(n, args) for n in names if finished(os.path.join(args.root, n, "run"))]
    if not table:
        sys.exit("no finished run to tabulate")
    path = os.path.join(args.root, "controlled_runs.csv")
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(table[0]))
        writer.writeheader()
        writer.writerows(table)
    for r in table:
        print(" | ".join(f"{v:.3g}" if isinstance(v, float) else str(v) for v in r.values()))
    print(f"table written: {path}")


if __name__ == "__main__":
    main()
