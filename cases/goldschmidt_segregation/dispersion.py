#!/usr/bin/env python3
"""How fast each class of spheres spreads through the bed: dispersion coefficients from the sphere dumps.

usage: dispersion.py CONTACTS [--tmin 0.3] [--lags 1 2 4]

CONTACTS: the folder of a run's contact dumps (goldschmidt.in, liggghts.variables.contact_period > 0; the
spheres are dumped at the first step of every burst, contact_period DEM steps apart). For every pair of bursts
LAG bursts apart that start at a coupled time of at least --tmin: per class (atom type), the variance of the
spheres' vertical and horizontal (x) displacements over the lag, halved and divided by the lag time, D_z and
D_x, and the class's mean vertical displacement (its drift). Printed per lag: the means over the pairs. For
beads and coarse-grained parcels of one bed over the same times, the ratio of their D says how much less (or
more) the parcels are mixed by the bed's motion.
"""
import argparse
import os

import numpy as np

from contact_exchange import bursts  # the same file, the same bursts


def burst_starts(folder, tmin):
    """(coupled time, sphere rows sorted by id) at the first step of every burst from tmin on."""
    starts = []
    for time, steps in bursts(folder, tmin):
        spheres = np.loadtxt(os.path.join(folder, f"atm.{steps[0]}.txt"), skiprows=9, ndmin=2)
        starts.append((time, spheres[np.argsort(spheres[:, 0])]))
    return starts


def dispersion(starts, lag):
    """{type: (D_z, D_x, drift_z)} averaged over the pairs of bursts lag apart, the pairs and their mean time
    apart; columns: id type mass radius x y z."""
    sums = {}
    pairs, apart = 0, 0.0
    for (t0, a), (t1, b) in zip(starts, starts[lag:]):
        if a.shape != b.shape or not np.array_equal(a[:, 0], b[:, 0]):
            raise SystemExit(f"the spheres at t = {t0:g} s and t = {t1:g} s are not the same ones (lost or inserted)")
        pairs += 1
        apart += t1 - t0
        for kind in np.unique(a[:, 1]).astype(int):
            s = a[:, 1] == kind
            dz, dx = b[s, 6] - a[s, 6], b[s, 4] - a[s, 4]
            row = np.array([np.var(dz), np.var(dx), 2 * (t1 - t0) * np.mean(dz)]) / (2 * (t1 - t0))
            sums[kind] = sums.get(kind, 0) + row
    return {k: v / pairs for k, v in sums.items()}, pairs, apart / max(pairs, 1)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("contacts")
    p.add_argument("--tmin", type=float, default=0.3, help="first coupled time of a burst [s]")
    p.add_argument("--lags", type=int, nargs="+", default=[1, 2, 4], help="lags in bursts")
    args = p.parse_args()
    starts = burst_starts(args.contacts, args.tmin)
    print(f"{args.contacts}: {len(starts)} bursts from t >= {args.tmin:g} s")
    for lag in args.lags:
        per_type, pairs, apart = dispersion(starts, lag)
        if not pairs:
            continue
        print(f"lag {apart:.3g} s ({pairs} pairs): " + "; ".join(
            f"type {k}: D_z {1e4 * v[0]:.2f} cm2/s, D_x {1e4 * v[1]:.2f} cm2/s, drift {1e3 * v[2]:+.2f} mm"
            for k, v in sorted(per_type.items())))


if __name__ == "__main__":
    main()
