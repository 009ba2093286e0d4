#!/usr/bin/python3
"""How strongly the bed moves at the scale of its bubbles: the solids' and the gas's box-averaged velocity
fluctuations from a run's field snapshots.

usage: mesoscale.py RUN [RUN ...] [--start 0] [--end T] [--box 3] [--slices]

Each snapshot (fields_*.h5: gas_fraction, gas_velocity, solids_velocity per cell) is averaged over the depth
onto the mesh's rows and columns (z, x) (with --slices, for a bed as deep as it is wide: taken on the slices at
1/4, 1/2 and 3/4 of the depth, each measured alone and the measures averaged), the solids velocity weighted by
the solids fraction and the gas velocity taken superficial (times the gas fraction), and then summed over boxes
of BOX x BOX of those cells, counting only the cells inside the bed (void_shape.py's surface); the mesh is a box
(no cut cells), x its width, y its depth. Per snapshot:
- solids: the variance of the boxes' solids velocity about the bed's centre-of-mass velocity, weighted by the
  boxes' solids (x and z), and that centre-of-mass velocity;
- gas: the variance of the boxes' superficial gas velocity about its mean inside the bed, weighted by the
  boxes' cells inside the bed.
Printed per run: the means of the variances over the snapshots in [start, end] and the rms of the centre-of-mass
velocity. Particle-scale agitation averages out in a box of several cells, so this is the motion that carries
the classes through the bed: beads and coarse-grained parcels of one bed compare here like for like (a parcel
and the beads it stands for deposit the same solids).
"""
import argparse
import glob
import os
import sys

import h5py
import numpy as np

import void_shape


def box_sums(field, inside, box):
    """Sums of field[z, x] over the cells inside the bed, per box of box x box cells."""
    nz, nx = field.shape
    out = np.zeros((-(-nz // box), -(-nx // box)))
    rows, cols = np.nonzero(inside)
    np.add.at(out, (rows // box, cols // box), field[rows, cols])
    return out


def planes(stacked, centres, slices):
    """The cell fields stacked[i, k] as planes [a[z, x, k], ...]: the depth average of a quasi-2D bed, or the
    slices of a bed as deep as it is wide (where a depth average would smooth its motion away)."""
    if slices:
        return [a for a, _ in void_shape.depth_slices(stacked, centres, void_shape.DEPTH_SLICES)]
    return [void_shape.depth_averaged(stacked, centres)[0]]


def plane_measure(averaged, box):
    """(solids variance x, z; centre-of-mass velocity x, z; gas variance x, z) of one plane of the stacked
    fields (gas fraction, solids fraction, solids momentum x, z, superficial gas velocity x, z)."""
    inside = void_shape.inside_bed(averaged[..., 0])
    s = box_sums(averaged[..., 1], inside, box)
    cells = box_sums(np.ones_like(averaged[..., 0]), inside, box)
    out_var, out_com, out_gas = [], [], []
    for k in range(2):  # x, z
        momentum = box_sums(averaged[..., 2 + k], inside, box)
        com = momentum.sum() / s.sum()
        held = s > 0
        out_var.append(float(np.sum(s[held] * (momentum[held] / s[held] - com) ** 2) / s.sum()))
        out_com.append(float(com))
        flux = box_sums(averaged[..., 4 + k], inside, box)
        mean = flux.sum() / cells.sum()
        held = cells > 0
        out_gas.append(float(np.sum(cells[held] * (flux[held] / cells[held] - mean) ** 2) / cells.sum()))
    return out_var + out_com + out_gas


def snapshot(gas_fraction, gas_velocity, solids_velocity, centres, box, slices=False):
    """(solids variance x, z; centre-of-mass velocity x, z; gas variance x, z) of one snapshot, per the module
    docstring (on slices: the mean over the slices); the fields given per cell at centres."""
    solids = 1.0 - gas_fraction
    stacked = np.column_stack([gas_fraction, solids, solids[:, None] * solids_velocity[:, (0, 2)],
                               gas_fraction[:, None] * gas_velocity[:, (0, 2)]])
    return list(np.mean([plane_measure(a, box) for a in planes(stacked, centres, slices)], axis=0))


def run_measure(folder, start, end, box, slices=False):
    """{"snapshots", "solids_var_x", "solids_var_z", "com_rms_x", "com_rms_z", "gas_var_x", "gas_var_z"} over the
    run's snapshots with start <= time <= end (SI units: m2/s2 and m/s); None without such a snapshot."""
    with h5py.File(os.path.join(folder, "fields_mesh.h5"), "r") as f:
        centres = np.asarray(f["points"]).reshape(-1, 8, 3).mean(axis=1)
    rows = []
    for path in sorted(glob.glob(os.path.join(folder, "fields_[0-9]*.h5"))):
        with h5py.File(path, "r") as f:
            time = float(np.asarray(f["time"])[0])
            if start - 1e-9 <= time <= end + 1e-9:
                rows.append(snapshot(np.asarray(f["gas_fraction"]), np.asarray(f["gas_velocity"]),
                                     np.asarray(f["solids_velocity"]), centres, box, slices))
    if not rows:
        return None
    r = np.array(rows)
    return {"snapshots": len(r), "solids_var_x": r[:, 0].mean(), "solids_var_z": r[:, 1].mean(),
            "com_rms_x": np.sqrt(np.mean(r[:, 2] ** 2)), "com_rms_z": np.sqrt(np.mean(r[:, 3] ** 2)),
            "gas_var_x": r[:, 4].mean(), "gas_var_z": r[:, 5].mean()}


def refuse(message):
    """Bad input: the message on stderr, exit status 2."""
    print(f"mesoscale.py: {message}", file=sys.stderr)
    sys.exit(2)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("runs", nargs="+", help="run folders (with fields_mesh.h5 and fields_*.h5)")
    p.add_argument("--start", type=float, default=0.0, help="first snapshot time [s]")
    p.add_argument("--end", type=float, default=float("inf"), help="last snapshot time [s]")
    p.add_argument("--box", type=int, default=3, help="box edge in cells")
    p.add_argument("--slices", action="store_true",
                   help="a bed as deep as it is wide: measure on the slices at 1/4, 1/2 and 3/4 of the depth and "
                        "average, instead of over the depth")
    args = p.parse_args()
    if args.box < 1:
        refuse(f"--box {args.box}: the box edge must be at least 1 cell")
    where = "on slices at 1/4, 1/2, 3/4 of the depth" if args.slices else "over the depth"
    print(f"boxes of {args.box} x {args.box} cells {where}, snapshots at t = {args.start:g}-{args.end:g} s; "
          "solids and gas box-velocity variance [cm2/s2], centre-of-mass velocity rms [cm/s]")
    print(f"{'run':40s} {'snaps':>5s} {'solids x':>9s} {'solids z':>9s} {'com x':>6s} {'com z':>6s} "
          f"{'gas x':>7s} {'gas z':>7s}")
    for folder in args.runs:
        m = run_measure(folder, args.start, args.end, args.box, args.slices)
        if m is None:
            refuse(f"{folder}: no field snapshot between t = {args.start:g} and {args.end:g} s")
        print(f"{folder[-40:]:40s} {m['snapshots']:5d} {1e4 * m['solids_var_x']:9.1f} {1e4 * m['solids_var_z']:9.1f} "
              f"{100 * m['com_rms_x']:6.2f} {100 * m['com_rms_z']:6.2f} {1e4 * m['gas_var_x']:7.0f} "
              f"{1e4 * m['gas_var_z']:7.0f}")


if __name__ == "__main__":
    main()
