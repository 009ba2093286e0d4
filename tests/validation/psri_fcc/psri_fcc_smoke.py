#!/usr/bin/python3
"""Smoke test of cases/psri_fcc_bubbling_bed (issue 12): the `smoke` variant as shipped (smoke/case.yaml: a
0.3 m column with exit tube and ring sparger, 2,000 parcels of 20 mm over the FCC distribution), run on the
ranks given, in a temporary copy of the case folder that is removed at the end. The case's gas mesh cuts its
cells with the column's cylinders (`mesh.walls: cut_cells`, issue 31); with `--walls staircase` the copy
selects whole cells by their centre instead, and its box's side patches get their wall entries back.

Checks:
- with cut cells, no parcel has its centre outside the gas's fluid cells at the start, and on either mesh
  none outside the geometry's column (no such warnings);
- the sparger's gas leaves through the outlet: at every field snapshot the flow through the top cell layer
  of the exit tube (a_g u_z times the cells' cross-section) equals the injected flow within 1 % (the
  parcels' volume in the column is constant but for parcels pending for a moment in the reinjection fix,
  so the gas volume is too; measured 0.12 %), and the time-averaged solids fraction in the tube is 0;
- the parcels circulate: their mean height changes by more than 0.05 m over the run and their mean speed in
  the last parcel snapshot is above 0.05 m/s;
- reinjection happened and kept the parcels: at every thermo line of the coupled phase in log.liggghts,
  atoms + pending (f_reinject[5]) = the initial count and cumulative out - in (f_reinject[7] - [9]) =
  pending; out > 0 at the end; the summary line's "N parcels lost" equals the pending count at the end
  and is 0 (parcelflow counts LIGGGHTS' atoms);
- monitors.csv (a row after the first gas step and then every monitor interval, finite values), the field and parcel snapshots
  (fields.xdmf, parcels.xdmf) and averages.csv / averages.xdmf are written and readable (h5py).

usage: psri_fcc_smoke.py [--walls staircase] PARCELFLOW MPIEXEC...
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ElementTree

import h5py
import numpy as np
import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, fail  # noqa: E402

CASE = os.path.join(CASES, "psri_fcc_bubbling_bed")


def xdmf_files(path, prefix):
    tree = ElementTree.parse(path)
    names = {item.text.strip().split(":")[0] for item in tree.iter("DataItem") if item.text and ".h5:" in item.text}
    return sorted(name for name in names if os.path.basename(name).startswith(prefix))


def reinjection_lines(log):
    """(step, atoms, pending, out, in) of every thermo line printed with the reinjection columns."""
    rows, active = [], False
    for line in open(log):
        parts = line.split()
        if parts[:2] == ["Step", "Atoms"]:
            active = parts[2:] == ["reinject"] * 3
            continue
        if active and len(parts) == 5 and parts[0].isdigit():
            rows.append([int(float(x)) for x in parts])
        elif active and parts and not parts[0].isdigit():
            active = False
    return rows


def check(out, stdout, settings):
    initial = int(re.search(r"parcelflow: (\d+) parcels, (\d+) gas cells", stdout).group(1))
    cells = int(re.search(r"parcelflow: (\d+) parcels, (\d+) gas cells", stdout).group(2))
    summary = [line for line in stdout.splitlines() if line.startswith("parcelflow: done")][-1]
    lost = int(re.search(r"(\d+) parcels lost$", summary.strip()).group(1))

    # Reinjection: the balance at every thermo line of the coupled phase.
    rows = reinjection_lines(os.path.join(out, "log.liggghts"))
    if len(rows) < 10:
        fail(f"log.liggghts has {len(rows)} thermo lines with the reinjection counters")
    bad = [r for r in rows if r[1] + r[2] != initial or r[3] - r[4] != r[2]]
    if bad:
        fail(f"reinjection balance broken (step, atoms, pending, out, in), first: {bad[0]}; initial {initial}")
    step, atoms, pending, total_out, total_in = rows[-1]
    max_pending = max(r[2] for r in rows)
    print(f"[measured] reinjection: {total_out} parcels out, {total_in} in, {pending} pending at the end "
          f"(at most {max_pending}); atoms + pending = {atoms + pending} = initial {initial} at all {len(rows)} lines")
    if total_out <= 0:
        fail("no parcel reached the outlet region")
    if lost != 0:
        fail(f"the summary reports {lost} parcels lost ({pending} pending at the end, which are not lost)")

    # Monitors: a row after the first gas step, then one every monitor interval; finite values.
    monitors = list(csv.DictReader(open(os.path.join(out, "monitors.csv"))))
    interval, end = settings["output"]["monitor_interval"], settings["time"]["end"]
    if len(monitors) != round(end / interval) + 1:
        fail(f"monitors.csv has {len(monitors)} rows, expected {round(end / interval) + 1}")
    for r in monitors:
        for key, value in r.items():  # type 2 is the walls' material: no parcels, NaN by definition
            if key != "mean_z_type2" and not math.isfinite(float(value)):
                fail(f"monitors.csv: {key} = {value} at t = {r['time']}")
    # monitors.csv's reinjection columns: the same totals as the fix, per-row counts that add up to them,
    # and no row with lost parcels (pending ones are in the run).
    last = monitors[-1]
    if float(last["reinjected_out_total"]) != total_out or float(last["reinjected_in_total"]) != total_in:
        fail(f"monitors.csv reinjection totals {last['reinjected_out_total']}/{last['reinjected_in_total']}, "
             f"the fix's {total_out}/{total_in}")
    if sum(float(r["reinjected_out"]) for r in monitors) != total_out:
        fail("monitors.csv's reinjected_out per row do not add up to the total")
    if any(float(r["lost_parcels"]) != 0 for r in monitors):
        fail("monitors.csv reports lost parcels")
    heights = np.array([float(r["mean_z_type1"]) for r in monitors])
    print(f"[measured] mean parcel height {heights[0]:.3f} m at the start, range {heights.min():.3f}-"
          f"{heights.max():.3f} m; bed pressure drop / weight at the end "
          f"{float(monitors[-1]['bed_pressure_drop']) / float(monitors[-1]['bed_weight_per_area']):.3f}")
    if heights.max() - heights.min() < 0.05:
        fail("the parcels' mean height changed by less than 0.05 m")

    # Fields and parcels: every snapshot readable.
    fields = xdmf_files(os.path.join(out, "fields.xdmf"), "fields_0")
    parcels = xdmf_files(os.path.join(out, "parcels.xdmf"), "parcels_0")
    if len(fields) < 2 or len(parcels) < 2:
        fail(f"{len(fields)} field and {len(parcels)} parcel snapshots listed, expected at least 2 each")
    for name in fields:
        with h5py.File(os.path.join(out, name), "r") as f:
            alpha = np.asarray(f["gas_fraction"])
            if alpha.shape != (cells,) or not ((alpha > 0) & (alpha <= 1)).all():
                fail(f"{name}: gas_fraction shape {alpha.shape}, range {alpha.min()}..{alpha.max()}")
    for name in parcels:
        with h5py.File(os.path.join(out, name), "r") as f:
            n = len(np.asarray(f["id"]))
            if n + 0 > initial or np.asarray(f["dp"]).min() < 9e-6 or np.asarray(f["dp"]).max() > 291e-6:
                fail(f"{name}: {n} parcels, dp {np.asarray(f['dp']).min()}..{np.asarray(f['dp']).max()}")
    with h5py.File(os.path.join(out, parcels[-1]), "r") as f:
        speed = np.linalg.norm(np.asarray(f["velocity"]), axis=1).mean()
        classes = len(np.unique(np.round(np.asarray(f["dp"]) * 1e6)))
    print(f"[measured] {len(fields)} field and {len(parcels)} parcel snapshots readable; mean parcel speed "
          f"{speed:.3f} m/s in the last, {classes} size classes present")
    if speed < 0.05:
        fail(f"mean parcel speed {speed} m/s in the last snapshot: the parcels do not move")

    # Time averages: averages.csv (profile, bed height) and the mean fields.
    lines = open(os.path.join(out, "averages.csv")).read().splitlines()
    header = re.search(r"time averages over ([0-9.e+-]+) s .*bed height (\S+) m", lines[0])
    if not header:
        fail(f"averages.csv: unexpected first line {lines[0]!r}")
    averaged = float(header.group(1))
    table = list(csv.DictReader(lines[1:]))
    planes = settings["monitors"]["pressure_planes"]
    if len([r for r in table if r["z"]]) != len(planes):
        fail(f"averages.csv: {len(table)} rows for {len(planes)} planes")
    averages = xdmf_files(os.path.join(out, "averages.xdmf"), "averages_0")
    with h5py.File(os.path.join(out, "fields_mesh.h5"), "r") as f:
        corners = np.asarray(f["points"]).reshape(-1, 8, 3)
        fluid_fraction = np.asarray(f["fluid_fraction"])
    centre, lo, hi = corners.mean(axis=1), corners.min(axis=1), corners.max(axis=1)
    with h5py.File(os.path.join(out, averages[-1]), "r") as f:
        mean_gas_speed = np.asarray(f["mean_gas_speed"])
        mean_solids = np.asarray(f["mean_solids_fraction"])
    if mean_gas_speed.shape != (cells,) or mean_solids.shape != (cells,):
        fail("averages: field sizes differ from the mesh")

    # Gas continuity: the injected flow leaves through the outlet. At every field snapshot the flow through
    # the top layer of the exit tube (a_g u_z times the cells' cross-section; no parcel above the lid) equals
    # the sparger's flow: the parcels' volume in the column is constant (but for parcels pending for a
    # moment in the reinjection fix), so the gas volume is too.
    injected = settings["inlet_regions"][0]["flow_rate"]
    lid = float(settings["liggghts"]["variables"]["H"])
    if not (mean_solids[centre[:, 2] > lid] == 0).all():
        fail("solids in the exit tube")
    # the tube's cells are prisms: a cut cell's open top is its fluid fraction of the box's
    open_area = (hi[:, 0] - lo[:, 0]) * (hi[:, 1] - lo[:, 1]) * fluid_fraction
    top = np.isclose(centre[:, 2], centre[:, 2].max())
    tube_area = open_area[top].sum()
    flows = []
    for name in fields:
        with h5py.File(os.path.join(out, name), "r") as f:
            flows.append(float((np.asarray(f["gas_velocity"])[top, 2] * np.asarray(f["gas_fraction"])[top] *
                                open_area[top]).sum()))
    error = max(abs(q - injected) for q in flows) / injected
    print(f"[measured] injected {injected:.6f} m3/s; flow out of the exit tube's top layer {min(flows):.6f}-"
          f"{max(flows):.6f} m3/s in {len(flows)} snapshots ({100 * error:.2f} %, allowed 1 %), gas speed "
          f"there {max(flows) / tube_area:.2f} m/s through {tube_area * 1e4:.1f} cm2 (the tube's circle "
          f"{math.pi * 0.05 ** 2 * 1e4:.1f}); averaged over {averaged:g} s: bed height "
          f"{header.group(2)} m")
    if error > 0.01:
        fail("the flow leaving through the exit tube differs from the sparger's flow")


def use_staircase(smoke):
    path = os.path.join(smoke, "case.yaml")
    settings = yaml.safe_load(open(path))
    settings["mesh"]["walls"] = "staircase"
    for side in ("xmin", "xmax", "ymin", "ymax"):
        settings["boundaries"][side] = {"type": "wall"}
    yaml.safe_dump(settings, open(path, "w"))


def main():
    args = sys.argv[1:]
    walls = "cut_cells"
    if args[:2] == ["--walls", "staircase"]:
        walls, args = "staircase", args[2:]
    parcelflow, launcher = args[0], args[1:]
    work = tempfile.mkdtemp(prefix="pf_psri_fcc_")
    try:
        case = os.path.join(work, "psri_fcc_bubbling_bed")
        shutil.copytree(CASE, case, ignore=shutil.ignore_patterns("output", "*.png"))
        smoke = os.path.join(case, "smoke")
        if walls == "staircase":
            use_staircase(smoke)
        settings = yaml.safe_load(open(os.path.join(smoke, "case.yaml")))
        out = os.path.join(work, "output")
        start = time.time()
        done = subprocess.run(launcher + [parcelflow, "run", smoke, "--output", out], capture_output=True,
                              text=True, errors="replace")
        wall = time.time() - start
        if done.returncode != 0:
            fail(f"parcelflow exited with {done.returncode}\n{done.stdout[-3000:]}{done.stderr[-3000:]}")
        summary = [line for line in done.stdout.splitlines() if line.startswith("parcelflow: done")]
        print(summary[-1] if summary else "(no summary line)")
        print(f"[measured] parcelflow run (filling, settling, coupled) took {wall:.0f} s wall ({walls})")
        outside = re.search(r"warning: .*parcels have their centre in no fluid cell.*", done.stdout)
        if outside:
            print(f"[measured] {outside.group(0)[:160]}")
            if walls == "cut_cells":
                fail("parcels outside the fluid cells of the cut-cell column at the start")
        if "outside case.yaml's geometry" in done.stdout:  # fcc_bed.in's walls are the geometry's cylinder
            fail("parcels outside the gas's geometry at the start: " +
                 re.search(r"warning: .*outside case.yaml's geometry.*", done.stdout).group(0)[:200])
        check(out, done.stdout, settings)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("PASS")


if __name__ == "__main__":
    main()
