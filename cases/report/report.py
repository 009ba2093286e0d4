#!/usr/bin/python3
"""The plots and statistics every bed needs, from any parcelflow run's output folder.

usage: report.py OUTPUT [--out DIR] [--start T]

Draws (each only when the run wrote what it needs; README.md here defines every plot and number):
  pressure_drop.png   bed pressure drop against the buoyant bed weight per area, and their ratio
  class_heights.png   the mean height of each class or atom type (the mean_z_* monitor columns)
  solids_fraction.png solids fraction on the vertical mid-depth plane at up to six field snapshots
  voids.png           the voids' share of the bed's cells and the bubbles per plane, per snapshot
  averages_profile.png, averages_fields.png   the time averages of monitors.average
  parcel_profiles.png each atom type's solid volume against height at the last parcel snapshot
and writes report.txt: the statistics over the window from --start (default: the second half of the run) to
the end. Exit status 2 for a folder that is not a run's output or a --start outside the run.
"""
import argparse
import os
import sys

import numpy as np

import figures
import mesoscale
import run_output
import void_shape

MAX_SNAPSHOT_PANELS = 6
MESOSCALE_BOX = 3  # cells: particle-scale agitation averages out, bubble-scale motion stays


def void_rows(mesh, snapshots):
    """Per snapshot [(time, gas_fraction)]: {time, void_share, bubbles, layer, widths, emulsion, spread}, the void
    share, bubbles, emulsion gas fraction and lateral spread as means over its planes (Mesh.void_planes), layer
    whether any plane has a bed-wide layer, widths those of every bubble."""
    rows = []
    dx = mesh.spacing[mesh.width_axis]
    for time, gas_fraction in snapshots:
        planes = mesh.void_planes(gas_fraction)
        measures = [void_shape.snapshot_measure(a, dx) for a in planes]
        holdups = [void_shape.holdup(a) for a in planes]
        emulsion = [h[1] for h in holdups if np.isfinite(h[1])]
        rows.append({"time": time, "void_share": float(np.mean([h[0] for h in holdups])),
                     "bubbles": float(np.mean([m[1] for m in measures])), "layer": any(m[0] for m in measures),
                     "widths": [w for m in measures for w in m[2]],
                     "emulsion": float(np.mean(emulsion)) if emulsion else float("nan"),
                     "spread": float(np.mean([void_shape.lateral_spread(a) for a in planes]))})
    return rows


def void_summary(rows):
    """{snapshots, void_share, bubbles_per_plane, bubble_width, layer_share, emulsion_gas_fraction,
    lateral_spread} over rows of void_rows (bubble width and emulsion NaN without any)."""
    widths = [w for r in rows for w in r["widths"]]
    emulsion = [r["emulsion"] for r in rows if np.isfinite(r["emulsion"])]
    return {"snapshots": len(rows), "void_share": float(np.mean([r["void_share"] for r in rows])),
            "bubbles_per_plane": float(np.mean([r["bubbles"] for r in rows])),
            "bubble_width": float(np.mean(widths)) if widths else float("nan"),
            "layer_share": float(np.mean([r["layer"] for r in rows])),
            "emulsion_gas_fraction": float(np.mean(emulsion)) if emulsion else float("nan"),
            "lateral_spread": float(np.mean([r["spread"] for r in rows]))}


def mesoscale_summary(mesh, snapshots_in_window):
    """mesoscale.py's measure over the window's snapshots [(time, path)] (None on a mesh of cut cells or without
    the velocity fields): solids' box-velocity variance x, z and the gas's, on the planes the voids use."""
    if not mesh.box or not snapshots_in_window:
        return None
    centres = mesh.width_first(mesh.centres)
    rows = []
    for _, path in snapshots_in_window:
        fields = [run_output.read_field(path, k) for k in ("gas_fraction", "gas_velocity", "solids_velocity")]
        if any(f is None for f in fields):
            return None
        rows.append(mesoscale.snapshot(fields[0], mesh.width_first(fields[1]), mesh.width_first(fields[2]), centres,
                                       MESOSCALE_BOX, slices=not mesh.thin()))
    r = np.array(rows)
    return {"solids_var_x": r[:, 0].mean(), "solids_var_z": r[:, 1].mean(), "gas_var_x": r[:, 4].mean(),
            "gas_var_z": r[:, 5].mean()}


def window_start(monitors, start):
    """The first time of the statistics window: start, or half the run's last monitor time."""
    end = monitors["time"][-1]
    if start is None:
        return 0.5 * end
    if not 0 <= start < end:
        raise run_output.NotARun(f"--start {start:g}: must lie in [0, {end:g}) s, the run's monitored times")
    return start


def monitor_part(monitors, start, out, title, labels):
    """The pressure drop and the class heights: (summary lines, PNGs)."""
    window = monitors["time"] >= start - 1e-12
    lines, written = [], []
    if "bed_pressure_drop" in monitors and "bed_weight_per_area" in monitors:
        dp, weight = monitors["bed_pressure_drop"][window], monitors["bed_weight_per_area"][window]
        lines.append(f"bed pressure drop {dp.mean():.4g} Pa, weight per area {weight.mean():.4g} Pa: "
                     f"dp/(W/A) {dp.mean() / weight.mean():.3f}, rms {dp.std() / weight.mean():.3f}")
        written.append(figures.pressure_drop(monitors, start, out, title=title))
    heights = run_output.height_columns(monitors)
    if heights:
        lines.append("mean height [mm] (mean, rms): " + ", ".join(
            f"{k} {1000 * np.nanmean(monitors[k][window]):.2f}, {1000 * np.nanstd(monitors[k][window]):.2f}"
            for k in heights))
        written.append(figures.class_heights(monitors, heights, start, out, title=title, labels=labels))
    return lines, written


def field_part(folder, snapshots, start, out, title, result):
    """The solids-fraction planes, the voids and the mesoscale motion of the field snapshots [(time, path)]:
    (summary lines, PNGs); sets result's mesh, voids and void_rows."""
    mesh = result["mesh"] = run_output.Mesh(os.path.join(folder, "fields_mesh.h5"))
    picked = [snapshots[int(i)] for i in np.linspace(0, len(snapshots) - 1, min(MAX_SNAPSHOT_PANELS, len(snapshots)))]
    written = [figures.solids_planes(mesh, [(time, run_output.read_field(path, "gas_fraction"))
                                            for time, path in picked], out, title=title)]
    rows = result["void_rows"] = void_rows(mesh, [(time, run_output.read_field(path, "gas_fraction"))
                                                  for time, path in snapshots])
    written.append(figures.voids(rows, start, out, title=title))
    in_window = [r for r in rows if r["time"] >= start - 1e-12]
    planes = "the depth average" if mesh.thin() else "slices at 1/4, 1/2, 3/4 of the depth"
    if not in_window:
        return ["voids: no field snapshot in the window"], written
    v = result["voids"] = void_summary(in_window)
    lines = [f"voids on {planes}, {v['snapshots']} snapshots: void share {v['void_share']:.3f}, "
             f"{v['bubbles_per_plane']:.2f} bubbles per plane, mean width {1000 * v['bubble_width']:.1f} mm, a "
             f"bed-wide layer in {100 * v['layer_share']:.0f} % of the snapshots, emulsion gas fraction "
             f"{v['emulsion_gas_fraction']:.3f}, lateral spread {v['lateral_spread']:.3f}"]
    motion = mesoscale_summary(mesh, [s for s in snapshots if s[0] >= start - 1e-12])
    if motion:
        lines.append(f"mesoscale motion (boxes of {MESOSCALE_BOX} x {MESOSCALE_BOX} cells, {planes}): solids "
                     f"box-velocity variance horizontal {1e4 * motion['solids_var_x']:.2f}, vertical "
                     f"{1e4 * motion['solids_var_z']:.2f} cm2/s2; gas horizontal {1e4 * motion['gas_var_x']:.1f}, "
                     f"vertical {1e4 * motion['gas_var_z']:.1f} cm2/s2")
    return lines, written


def averages_part(folder, out):
    """The time averages of monitors.average (averages.csv, averages_*.h5): (summary lines, PNGs)."""
    lines, written = [], []
    averages = run_output.read_averages_csv(folder)
    if averages and {"z", "mean_pressure", "interval_mid_z", "dp_over_g_dz"} <= set(averages[1]):
        lines.append(averages[0].lstrip("# "))
        written.append(figures.averaged_profile(*averages, out))
    averaged = run_output.series(folder, "averages")
    if averaged:
        time, path = averaged[-1]
        mesh = run_output.Mesh(os.path.join(folder, "averages_mesh.h5"))
        fields = {k: run_output.read_field(path, k) for k in ("mean_solids_fraction", "mean_gas_speed",
                                                               "mean_solids_speed")}
        written.append(figures.averaged_fields(mesh, {k: v for k, v in fields.items() if v is not None}, time, out))
    return lines, written


def parcel_part(folder, out, title, labels):
    """The height profile of each atom type at the last parcel snapshot: (summary lines, PNGs)."""
    snapshots = run_output.series(folder, "parcels")
    if not snapshots:
        return [], []
    time, path = snapshots[-1]
    parcels = run_output.read_parcels(path)
    if not len(parcels["z"]):
        return [f"parcels at t = {time:g} s: none"], []
    counts = ", ".join(f"type {k} {np.sum(parcels['type'] == k)}" for k in np.unique(parcels["type"]))
    return ([f"parcels at t = {time:g} s: {len(parcels['z'])} ({counts})"],
            [figures.parcel_profiles(parcels, time, out, title=title, labels=labels)])


def make(folder, out=None, start=None, title="", labels=None):
    """Draws the report of the run in folder into out (default: folder/report), titled title, the height columns
    named by labels {column: name}, and returns
    {"lines": summary lines, "written": [paths], "start": window start, "monitors", "mesh", "snapshots":
    [(time, path)], "voids": void_summary or None, "void_rows"}."""
    monitors = run_output.read_monitors(folder)
    start = window_start(monitors, start)
    out = out or os.path.join(folder, "report")
    os.makedirs(out, exist_ok=True)
    t = monitors["time"]
    prefix = f"{title}: " if title else ""
    result = {"lines": [f"{prefix}{folder}: monitors {t[0]:g}-{t[-1]:g} s ({len(t)} rows); statistics over "
                        f"{t[t >= start - 1e-12][0]:g}-{t[-1]:g} s"],
              "written": [], "start": start, "monitors": monitors, "mesh": None,
              "snapshots": run_output.series(folder, "fields"), "voids": None, "void_rows": []}
    parts = [monitor_part(monitors, start, out, title, labels)]
    if result["snapshots"]:
        parts.append(field_part(folder, result["snapshots"], start, out, title, result))
    parts.append(averages_part(folder, out))
    parts.append(parcel_part(folder, out, title, labels))
    for lines, written in parts:
        result["lines"] += lines
        result["written"] += written
    with open(os.path.join(out, "report.txt"), "w") as f:
        f.write("\n".join(result["lines"]) + "\n")
    result["written"].append(os.path.join(out, "report.txt"))
    return result


def draw(folder, **options):
    """make(folder, **options) for a script: prints the summary and the files written and returns make's result;
    a folder that is not a run's output (or a bad start) ends the script with its message and exit status 2."""
    try:
        result = make(folder, **options)
    except run_output.NotARun as e:
        print(f"{os.path.basename(sys.argv[0])}: {e}", file=sys.stderr)
        sys.exit(2)
    print("\n".join(result["lines"]))
    for path in result["written"]:
        print(f"written: {path}")
    return result


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("output", help="a run's output folder (monitors.csv, fields_*.h5, ...)")
    p.add_argument("--out", help="where the PNGs and report.txt go (default: OUTPUT/report)")
    p.add_argument("--start", type=float, help="first time of the statistics window [s] (default: half the run)")
    args = p.parse_args(argv)
    draw(args.output, out=args.out, start=args.start)


if __name__ == "__main__":
    main()
