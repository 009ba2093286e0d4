#!/usr/bin/env python3
"""Fluidized coarse-graining validation (issue 29, part 3): the Goldschmidt bead mixture (1.5 and 2.5 mm glass,
50/50 by mass) in a bed as deep as it is wide, fine (one bead per parcel) against np 8, np 27 and 5 mm parcels
of both classes, with one table: quantity, fine, coarse, difference, tolerance, pass (README.md here).

The bed is cases/goldschmidt_segregation with another box (its script takes width, depth, height and the
bead count), so every variant is made by that case's `coarse_graining.py` (same solid mass, parcels, contact
scaling, DEM step). The inlet velocity rises linearly from 0 to HOLD_VELOCITY over RAMP_TIME and then holds:
- U_mf: the packed branch dp = a U + b U^2 (Ergun's form), fitted to the ramp's points before dp first reaches
  PACKED_SHARE of the fluidized plateau, meets the plateau (the mean bed pressure drop over the window);
- over the window (the hold): dp/(W/A), the bed expansion (the mass-weighted mean height of the beads over
  the window against the settled bed's at the first monitor row), bubbles per slice and their width
  (`void_shape.py` on three slices across the depth, at 1/4, 1/2 and 3/4).
A variant that finished before with the same settings is not run again (coarse_graining.py keeps it).

usage: validate.py PARCELFLOW [--runs DIR] [--size smoke|full|periodic|deep] [--ranks N] [--jobs N] [--mpirun CMD]
                   [--require-pass] [--restitution E] [--seed N] [--checkpoint-interval T] [--set KEY=VALUE ...]
                   [--variants fine [VARIANT ...]]
A fine bed alone (no coarse variant) is run and measured without a table, as a reference for later pairs.
"""
import argparse
import csv
import glob
import math
import os
import shutil
import subprocess
import sys
import time

import h5py
import numpy as np
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
GOLDSCHMIDT = os.path.normpath(os.path.join(HERE, "..", "..", "goldschmidt_segregation"))
sys.path.insert(0, GOLDSCHMIDT)
sys.path.insert(0, os.path.normpath(os.path.join(HERE, "..", "..", "report")))
from coarse_graining import FINE_VARIANTS, RESTITUTION  # noqa: E402
import mesoscale  # noqa: E402
import void_shape  # noqa: E402

VARIANTS = ("fine", "np8_linear", "np27_linear", "d5mm_linear")
PACKED_SHARE = 0.85
# quantity: (relative tolerance of coarse against fine, unit, what it is)
QUANTITIES = {
    "u_mf": (0.05, "m/s", "minimum fluidization velocity from the ramp"),
    "dp_over_weight": (0.05, "", "bed pressure drop over the beads' weight per area, window mean"),
    "expansion": (0.05, "", "mean bead height over the window / the settled bed's"),
    "void_share": (0.15, "", "share of the bed's cells in voids, voids that span the box included (slices)"),
    "dp_rms_over_weight": (0.15, "", "rms of the bed pressure drop about its window mean, over the weight per area"),
    "height_rms_mm": (0.15, "mm", "rms of the beads' mean height about its window mean"),
}
# Printed beside the table, without a tolerance: the voids counted one by one (a void that spans the box is not
# counted, so in a narrow box most of them drop out), where the expansion sits and how much the solids move.
DIAGNOSTICS = {
    "bubbles_per_slice": "voids of the void measure per slice and snapshot (box-spanning ones dropped)",
    "bubble_width_mm": "mean width of those voids [mm]",
    "emulsion_gas_fraction": "mean gas fraction of the bed's cells outside voids",
    "solids_motion_z_cm2s2": "vertical box-velocity variance of the solids (mesoscale.py --slices, 3 x 3 cells)",
}

# The bed per size. Full: 75 x 75 mm (the 7.5 mm np 27 parcels are 10 across), 45,000 beads (a static bed of
# about 40 mm), 3.26 mm cells (the Goldschmidt case's size), 0.15 m tall. The inlet reaches 1.3 m/s, about
# 1.9 U_mf of the fine bed (a first ramp to 1.8 m/s reached the beads' weight at about 0.7 m/s; Wen-Yu's
# correlation gives 0.84 m/s for 1.5 mm and 1.26 m/s for 2.5 mm beads). Smoke: a 20 mm bed of 800 beads for
# 0.3 s, to check that the driver and the codes run (not the physics). Periodic: a quarter of the full bed's
# area (37.5 x 37.5 mm, 11,250 beads, 3.125 mm cells) with periodic sides for the parcels and free-slip side
# walls for the gas, a cut from an unbounded bed: no wall for the parcels' packing to loosen against. Deep: the
# periodic box with twice the beads (a static bed of about 72 mm: 14 np 8 parcels, 10 np 27 parcels tall), so
# that the plate's and the surface's layers, a few parcel diameters each, are a smaller share of the bed; the
# filling falls at 0.3 m/s (coarse_graining.py), so the settling is 0.75 s.
SIZES = {
    "full": {"width": 0.075, "height": 0.15, "nbeads": 45000, "fill_top": 0.094, "settle_steps": 5000,
             "cells": [23, 23, 46], "end": 7.0, "ramp_time": 3.0, "window": 4.0, "hold_velocity": 1.3},
    "periodic": {"width": 0.0375, "height": 0.15, "nbeads": 11250, "fill_top": 0.094, "settle_steps": 5000,
                 "cells": [12, 12, 48], "end": 7.0, "ramp_time": 3.0, "window": 4.0, "hold_velocity": 1.3,
                 "periodic_sides": True},
    "deep": {"width": 0.0375, "height": 0.3125, "nbeads": 22500, "fill_top": 0.19, "settle_steps": 18000,
             "cells": [12, 12, 100], "end": 5.5, "ramp_time": 3.0, "window": 4.0, "hold_velocity": 1.3,
             "periodic_sides": True},
    "smoke": {"width": 0.02, "height": 0.08, "nbeads": 800, "fill_top": 0.030, "settle_steps": 2000,
              "cells": [6, 6, 24], "end": 0.3, "ramp_time": 0.2, "window": 0.2, "hold_velocity": 1.8},
}


def make_bed(size, runs):
    """RUNS/bed: the Goldschmidt case with this size's box, bead count, mesh, ramped inlet and monitors."""
    geometry = SIZES[size]
    bed = os.path.join(runs, "bed")
    shutil.rmtree(bed, ignore_errors=True)
    shutil.copytree(GOLDSCHMIDT, bed, ignore=shutil.ignore_patterns("output", "__pycache__", "*.png"))
    config = yaml.safe_load(open(os.path.join(bed, "case.yaml")))
    width, height = geometry["width"], geometry["height"]
    config["liggghts"]["variables"].update(
        width=repr(width), depth=repr(width), height=repr(height), nbeads=str(geometry["nbeads"]),
        fill_top=repr(geometry["fill_top"]), settle_steps=str(geometry["settle_steps"]))
    config["mesh"]["lengths"] = [width, width, height]
    config["mesh"]["cells"] = geometry["cells"]
    config["time"]["end"] = geometry["end"]
    if geometry.get("periodic_sides"):
        config["liggghts"]["variables"]["periodic_sides"] = "1"
        for side in ("xmin", "xmax", "ymin", "ymax"):
            config["boundaries"][side] = {"type": "wall", "slip": "free_slip"}
    config["boundaries"]["zmin"] = {"type": "velocity_inlet", "superficial_velocity": [0, 0, geometry["hold_velocity"]],
                                    "ramp_time": geometry["ramp_time"]}
    top = height - 2 * height / geometry["cells"][2]  # a plane below the outlet cells
    config["monitors"] = {"pressure_planes": [0.0, top], "bed_pressure_drop": [0.0, top]}
    config["output"]["fields_interval"] = 0.1 if size == "full" else 0.05
    with open(os.path.join(bed, "case.yaml"), "w") as f:
        yaml.safe_dump(config, f, sort_keys=False)
    return bed


def packed_branch_umf(velocity, dp, plateau):
    """U where the least-squares fit dp = a U + b U^2 of the packed points reaches the plateau (nan if none).
    Packed: the ramp's points before dp first reaches PACKED_SHARE of the plateau (a fluidized bed's pressure
    drop dips below that share too, and those points are not on the packed branch)."""
    reached = np.nonzero(dp >= PACKED_SHARE * plateau)[0]
    before = np.arange(len(dp)) < (reached[0] if len(reached) else len(dp))
    packed = before & (velocity > 0.05 * velocity.max())
    if packed.sum() < 5:
        return math.nan
    design = np.column_stack([velocity[packed], velocity[packed] ** 2])
    (a, b), *_ = np.linalg.lstsq(design, dp[packed], rcond=None)
    roots = [r.real for r in np.roots([b, a, -plateau]) if abs(r.imag) < 1e-12 and r.real > 0]
    return min(roots) if roots else math.nan


def measure(run, geometry):
    """The table's quantities of one finished run."""
    rows = list(csv.DictReader(open(os.path.join(run, "monitors.csv"))))
    column = {k: np.array([float(r[k]) for r in rows]) for k in
              ("time", "bed_pressure_drop", "bed_weight_per_area", "mean_z_type1", "mean_z_type2")}
    t = column["time"]
    velocity = geometry["hold_velocity"] * np.minimum(1.0, t / geometry["ramp_time"])
    window = t >= geometry["window"] - 1e-9
    plateau = column["bed_pressure_drop"][window].mean()
    height = 0.5 * (column["mean_z_type1"] + column["mean_z_type2"])  # 50/50 by mass
    ramp = t <= geometry["ramp_time"] + 1e-9
    with h5py.File(os.path.join(run, "fields_mesh.h5"), "r") as f:
        centres = np.asarray(f["points"]).reshape(-1, 8, 3).mean(axis=1)
    counts, widths, holdups, motion = [], [], [], []
    for path in sorted(glob.glob(os.path.join(run, "fields_[0-9]*.h5"))):
        with h5py.File(path, "r") as f:
            if float(np.asarray(f["time"])[0]) < geometry["window"] - 1e-9:
                continue
            gas_fraction, gas_velocity, solids_velocity = (np.asarray(f[k]) for k in
                                                           ("gas_fraction", "gas_velocity", "solids_velocity"))
        for a, dx in void_shape.depth_slices(gas_fraction.ravel(), centres, void_shape.DEPTH_SLICES):
            _, count, w = void_shape.snapshot_measure(a, dx)
            counts.append(count)
            widths += w
            holdups.append(void_shape.holdup(a))
        motion.append(mesoscale.snapshot(gas_fraction, gas_velocity, solids_velocity, centres, 3, slices=True)[1])
    return {"u_mf": packed_branch_umf(velocity[ramp], column["bed_pressure_drop"][ramp], plateau),
            "dp_over_weight": plateau / column["bed_weight_per_area"][window].mean(),
            "expansion": height[window].mean() / height[0],
            "dp_rms_over_weight": column["bed_pressure_drop"][window].std() / column["bed_weight_per_area"][window].mean(),
            "height_rms_mm": 1000 * height[window].std(),
            "bubbles_per_slice": float(np.mean(counts)) if counts else math.nan,
            "bubble_width_mm": 1000 * float(np.mean(widths)) if widths else math.nan,
            "void_share": float(np.mean([h[0] for h in holdups])) if holdups else math.nan,
            "emulsion_gas_fraction": float(np.nanmean([h[1] for h in holdups])) if holdups else math.nan,
            "solids_motion_z_cm2s2": 1e4 * float(np.mean(motion)) if motion else math.nan}


RECORD_KEY = ("size", "restitution", "seed", "settings", "variant")


def binary_commit(parcelflow):
    """The commit a binary was built from: the suffix of a copied binary (parcelflow-<commit>), else the build's
    source tree's HEAD."""
    name = os.path.basename(parcelflow)
    if name.startswith("parcelflow-"):
        return name[len("parcelflow-"):]
    source = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(parcelflow))))
    head = subprocess.run(["git", "-C", source, "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
    return head.stdout.strip() or "unknown"


def record(args, runs, measured, settings):
    """One row per variant in the run record args.record, replacing a row of the same bed, seed and variant."""
    beds = {r["variant"]: r for r in csv.DictReader(open(os.path.join(runs, "coarse_graining.csv")))}
    rows = []
    for variant, values in measured.items():
        bed = beds[variant]
        rows.append({"date": time.strftime("%Y-%m-%d", time.gmtime()), "commit": binary_commit(args.parcelflow),
                     "size": args.size, "restitution": args.restitution or RESTITUTION, "seed": args.seed or "script",
                     "settings": " ".join(s for s in settings if "insert_seed" not in s and "checkpoint" not in s),
                     "variant": variant, "ranks": args.ranks, "parcels": bed["parcels"],
                     "wall_s": bed["total_wall_s"], **{k: f"{v:.6g}" for k, v in values.items()}})
    old = list(csv.DictReader(open(args.record))) if os.path.exists(args.record) else []
    new_keys = {tuple(str(r[k]) for k in RECORD_KEY) for r in rows}
    kept = [r for r in old if tuple(r[k] for k in RECORD_KEY) not in new_keys]
    os.makedirs(os.path.dirname(os.path.abspath(args.record)), exist_ok=True)
    with open(args.record, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(kept + rows)
    print(f"recorded {len(rows)} run(s) in {args.record}")


def relative_difference(coarse, fine):
    """coarse / fine - 1; 0 when both are the same (no bubbles in either: counts 0, widths nan)."""
    if coarse == fine or (math.isnan(coarse) and math.isnan(fine)):
        return 0.0
    return coarse / fine - 1 if fine and math.isfinite(fine) else math.nan


def table_rows(measured):
    """Every variant's quantities against the first variant's (the fine bed)."""
    reference, *others = measured
    fine = measured[reference]
    rows = []
    for variant in others:
        values = measured[variant]
        for name, (tolerance, unit, _) in QUANTITIES.items():
            difference = relative_difference(values[name], fine[name])
            rows.append({"quantity": name, "unit": unit, "variant": variant, "fine": fine[name],
                         "coarse": values[name], "difference": difference, "tolerance": tolerance,
                         "pass": bool(abs(difference) <= tolerance)})
    return rows


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("parcelflow")
    p.add_argument("--runs", default=os.path.join(os.getcwd(), "coarse_graining_fluidized"))
    p.add_argument("--size", choices=sorted(SIZES), default="full")
    p.add_argument("--ranks", type=int, default=2)
    p.add_argument("--mpirun", default="mpirun")
    p.add_argument("--jobs", type=int, default=1, help="variants run at the same time (each on --ranks ranks)")
    p.add_argument("--require-pass", action="store_true", help="exit 1 unless every row passes")
    p.add_argument("--restitution", type=float, help="the beads' restitution (coarse_graining.py --restitution)")
    p.add_argument("--seed", type=int, help="LIGGGHTS' insertion seed, a prime above 10000 (default: the script's)")
    p.add_argument("--checkpoint-interval", type=float,
                   help="simulated seconds between checkpoints; a run stopped or killed continues from its newest")
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", help="coarse_graining.py --set")
    p.add_argument("--record", metavar="CSV", help="adds (or replaces) one row per variant in this run record, "
                   "e.g. cases/coarse_graining/fluidized/records/runs.csv; report.py draws the tables from it")
    p.add_argument("--variants", nargs="+", default=list(VARIANTS),
                   help="coarse_graining.py's variants, the fine bed first (e.g. mono_fine mono_np8_linear: beads of "
                        "one size)")
    args = p.parse_args()
    if args.variants[0] not in FINE_VARIANTS:
        p.error(f"--variants {' '.join(args.variants)}: the first must be a fine bed ({' or '.join(FINE_VARIANTS)})")
    runs = os.path.abspath(args.runs)
    os.makedirs(runs, exist_ok=True)
    geometry = SIZES[args.size]
    bed = make_bed(args.size, runs)
    command = [sys.executable, os.path.join(GOLDSCHMIDT, "coarse_graining.py"), os.path.abspath(args.parcelflow), runs,
               "--case", bed, "--end", str(geometry["end"]), "--start", str(geometry["window"]),
               "--ranks", str(args.ranks), "--jobs", str(args.jobs), "--mpirun", args.mpirun, *args.variants]
    if args.restitution is not None:
        command += ["--restitution", str(args.restitution)]
    settings = list(args.set)
    if args.seed is not None:
        settings.append(f"liggghts.variables.insert_seed={args.seed}")
    if args.checkpoint_interval is not None:
        settings.append(f"output.checkpoint_interval={args.checkpoint_interval}")
    command += [f"--set={setting}" for setting in settings]
    if subprocess.run(command).returncode != 0:
        sys.exit("coarse_graining.py failed (its output is above)")
    measured = {v: measure(os.path.join(runs, v, "run"), geometry) for v in args.variants}
    if args.record:
        record(args, runs, measured, settings)
    if len(measured) == 1:  # a fine reference alone
        print("\n".join(f"{name:22s} {value:.5g}" for name, value in measured[args.variants[0]].items()))
        return
    rows = table_rows(measured)
    path = os.path.join(runs, "coarse_graining_fluidized.csv")
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print(f"\n{'quantity':18s} {'variant':12s} {'fine':>10s} {'coarse':>10s} {'diff':>8s} {'tol':>5s}  pass")
    for r in rows:
        print(f"{r['quantity']:18s} {r['variant']:12s} {r['fine']:10.4g} {r['coarse']:10.4g} "
              f"{100 * r['difference']:+7.1f}% {100 * r['tolerance']:4.0f}%  {'yes' if r['pass'] else 'NO'}")
    print(f"table written: {path}\n\n{'diagnostic':22s}" + "".join(f"{v:>16s}" for v in args.variants))
    for name, what in DIAGNOSTICS.items():
        print(f"{name:22s}" + "".join(f"{measured[v][name]:16.4g}" for v in args.variants) + f"   {what}")
    if args.require_pass and not all(r["pass"] for r in rows):
        sys.exit(1)


if __name__ == "__main__":
    main()
