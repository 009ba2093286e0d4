#!/usr/bin/env python3
"""The classes' granular temperatures as coupling.class_collisions estimates them, from parcel snapshots.

usage: class_temperature.py RUN [RUN ...]   (RUN: a run folder of coarse_graining.py, e.g. OUT/np8_linear/run)

For every snapshot after t = 0 (parcels_*.h5), at every gas-cell centre where the kernel's solids fraction is
at least 0.3 and both classes (atom types 1 and 2) are present: each class's mass-weighted mean velocity and
velocity variance over the parcels with the case's Gaussian weights exp(-a |x - x_c|^2 / h^2), h the cube root
of the cell volume (periodic in y when liggghts.variables.periodic_depth is 1), the number of parcels that
variance stands on, n = (sum w m)^2 / sum (w m)^2, and the variance made unbiased, times n / (n - 1), as
coupling.class_collisions takes it. Printed: the means over those cells weighted by the class's mass there.
A fine run (np 1) gives the beads' own temperatures; thinning it to every 8th bead (--thin 8) shows what the
estimate of np 8 would be if parcels moved as beads do.
"""
import argparse
import glob
import os

import h5py
import numpy as np
import yaml
from scipy.spatial import cKDTree


def snapshot_temperatures(f, mesh, sharpness, periodic_depth, thin, rng):
    x, v, t = f["position"][:], f["velocity"][:], f["type"][:]
    dp, npp = f["dp"][:], f["np"][:]
    if thin > 1:
        keep = np.sort(rng.choice(len(t), len(t) // thin, replace=False))
        x, v, t, dp, npp = x[keep], v[keep], t[keep], dp[keep], npp[keep] * thin
    mass = npp * dp ** 3  # the density is common to both classes and cancels
    volume = np.pi / 6 * mass
    lengths, cells = np.array(mesh["lengths"]), np.array(mesh["cells"])
    spacing = lengths / cells
    h = np.prod(spacing) ** (1 / 3)
    if periodic_depth:
        shift = np.array([0.0, lengths[1], 0.0])
        x, v, t, mass, volume = (np.concatenate([x, x + shift, x - shift]), np.tile(v, (3, 1)), np.tile(t, 3),
                                 np.tile(mass, 3), np.tile(volume, 3))
    centres = np.stack(np.meshgrid(*[(np.arange(n) + 0.5) * s for n, s in zip(cells, spacing)], indexing="ij"),
                       axis=-1).reshape(-1, 3)
    reach = 3.0 * h / np.sqrt(sharpness)
    rows = {1: [], 2: []}
    for centre, near in zip(centres, cKDTree(x).query_ball_point(centres, reach)):
        near = np.asarray(near, dtype=int)
        if near.size == 0:
            continue
        w = np.exp(-sharpness * np.sum((x[near] - centre) ** 2, axis=1) / h ** 2)
        if np.sum(w * volume[near]) / (np.pi * h * h / sharpness) ** 1.5 < 0.3:
            continue
        per_class = {}
        for k in (1, 2):
            s = t[near] == k
            wm = w[s] * mass[near][s]
            if wm.sum() <= 0:
                break
            mean = wm @ v[near][s] / wm.sum()
            spread = (wm @ np.sum((v[near][s] - mean) ** 2, axis=1)) / wm.sum() / 3
            n = wm.sum() ** 2 / np.sum(wm ** 2)
            unbiased = spread * n / (n - 1) if n - 1 > 1e-9 else 0.0
            per_class[k] = (spread, unbiased, n, wm.sum())
        if len(per_class) == 2:
            for k in (1, 2):
                rows[k].append(per_class[k])
    return {k: np.average(np.array(r)[:, :3], weights=np.array(r)[:, 3], axis=0) for k, r in rows.items()}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("runs", nargs="+")
    p.add_argument("--thin", type=int, default=1, help="keep every THIN-th parcel at THIN times its mass")
    args = p.parse_args()
    rng = np.random.default_rng(1)
    print("run, t [s], type: temperature [m2/s2] as taken / unbiased, parcels n")
    for run in args.runs:
        case = yaml.safe_load(open(os.path.join(run, "request.yaml")))["case"]
        kernel = case["coupling"].get("kernel", {})
        periodic = int(case["liggghts"].get("variables", {}).get("periodic_depth", 0)) == 1
        for path in sorted(glob.glob(os.path.join(run, "parcels_*.h5"))):
            with h5py.File(path, "r") as snapshot:
                time = float(snapshot["time"][0])
                if time <= 0.01:
                    continue
                r = snapshot_temperatures(snapshot, case["mesh"], kernel.get("sharpness", 1.0), periodic, args.thin,
                                          rng)
            print(f"{run}, {time:g}, " + "; ".join(
                f"type {k}: {r[k][0]:.3e} / {r[k][1]:.3e}, n {r[k][2]:.1f}" for k in (1, 2)))


if __name__ == "__main__":
    main()
