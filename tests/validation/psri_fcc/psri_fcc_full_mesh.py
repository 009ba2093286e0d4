#!/usr/bin/python3
"""The full PSRI FCC case's gas mesh (cases/psri_fcc_bubbling_bed as shipped: 45 mm cut cells, the 0.2 m exit tube
on the 0.9 m column's lid) with 2,000 parcels instead of 540,804, for 0.3 s of its sparger's ramp, in a temporary
copy of the case folder that is removed at the end.

The lid (z = 7.0) must lie on a cell face: with the case's height written 7.4935897 it lay 4e-8 m above one, the
cells above it held a film of the column across their bottom faces besides their part of the tube (0.145 of a cell
along the tube's wall), and within 0.005 s they carried radial gas speeds growing to 60,000 m/s: the run diverged at
t = 0.10-0.13 s. Checks:
- the run ends normally (no divergence guard);
- the tube's cells from 0.1 m above the lid up hold the tube's volume (fluid fraction times box) within 0.5 %, so
  none is merged into a cell outside them, and at every field snapshot from t = 0.1 s their fluid-volume weighted
  mean u_z, the flow through the tube over its circle, equals the sparger's flow at that time (its ramp) over the
  circle within 1 % (measured +0.4 %; with the film 11-30 times it, where the run was kept from diverging);
- no gas above the lid is faster than 3 times that mean (the spurious speeds were 110-850 times it).

usage: psri_fcc_full_mesh.py PARCELFLOW MPIEXEC...
"""
import glob
import math
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np
import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, copy_case, fail  # noqa: E402

END = 0.3
FIRST_CHECKED = 0.1   # s: before it the flow is below 5 % of the full one
SPEED_TOLERANCE = 0.01
VOLUME_TOLERANCE = 0.005
SPEED_RATIO = 3.0


def few_parcels(settings):
    settings["liggghts"]["variables"].update({"fill_lattice": "0", "nparcels": "2000", "settle_steps": "400",
                                              "relax_steps": "200"})
    settings["output"].update({"fields_interval": 0.05, "parcels_interval": 0, "checkpoint_interval": 0,
                               "progress_interval": 1e6})


def main():
    parcelflow, launcher = sys.argv[1], sys.argv[2:]
    with tempfile.TemporaryDirectory(prefix="pf_fcc_full_mesh_") as work:
        case = copy_case(os.path.join(CASES, "psri_fcc_bubbling_bed"), work, few_parcels)
        settings = yaml.safe_load(open(os.path.join(case, "case.yaml")))
        out = os.path.join(work, "output")
        done = subprocess.run(launcher + [parcelflow, "run", case, "--output", out, "--end", repr(END)],
                              capture_output=True, text=True, errors="replace")
        if done.returncode != 0:
            fail(f"parcelflow exited with {done.returncode}\n{done.stdout[-3000:]}{done.stderr[-3000:]}")
        with h5py.File(os.path.join(out, "fields_mesh.h5"), "r") as f:
            points = np.asarray(f["points"]).reshape(-1, 8, 3)
            fluid_volume = np.prod(points.max(axis=1) - points.min(axis=1), axis=1) * np.asarray(f["fluid_fraction"])
        centre = points.mean(axis=1)
        lid = float(settings["liggghts"]["variables"]["H"])
        tube = next(g["shape"]["cylinder"] for g in settings["geometry"] if g["shape"]["cylinder"]["zmin"] >= lid)
        tube_area = math.pi * tube["radius"] ** 2
        above_lid, upper_tube = centre[:, 2] > lid, centre[:, 2] > lid + 0.1
        length = points[upper_tube, :, 2].max() - points[upper_tube, :, 2].min()
        volume = float(fluid_volume[upper_tube].sum())
        print(f"[measured] the tube's cells from 0.1 m above the lid hold {volume:.6g} m3 of fluid, the tube "
              f"{tube_area * length:.6g} m3")
        if abs(volume / (tube_area * length) - 1) > VOLUME_TOLERANCE:
            fail("the tube's cells do not hold the tube's volume (merged cells?)")
        sparger = settings["inlet_regions"][0]
        checked = 0
        for path in sorted(glob.glob(os.path.join(out, "fields_[0-9]*.h5"))):
            with h5py.File(path, "r") as f:
                t = float(np.asarray(f["time"])[0])
                u = np.asarray(f["gas_velocity"])
            if t < FIRST_CHECKED - 1e-9:
                continue
            mean_speed = sparger["flow_rate"] * min(1.0, t / sparger["ramp_time"]) / tube_area
            tube_speed = float((u[upper_tube, 2] * fluid_volume[upper_tube]).sum() / volume)
            fastest = float(np.linalg.norm(u[above_lid], axis=1).max())
            print(f"[measured] t = {t:.2f} s: sparger's flow over the tube's circle {mean_speed:.4g} m/s, the tube's "
                  f"volume-weighted u_z {tube_speed:.4g} m/s ({100 * (tube_speed / mean_speed - 1):+.2f} %, allowed "
                  f"{100 * SPEED_TOLERANCE:g} %); fastest gas above the lid {fastest:.3g} m/s, "
                  f"{fastest / mean_speed:.2f} times the mean (allowed {SPEED_RATIO:g})")
            if abs(tube_speed / mean_speed - 1) > SPEED_TOLERANCE:
                fail("the flow through the exit tube differs from the sparger's")
            if fastest > SPEED_RATIO * mean_speed:
                fail("spurious gas speeds above the lid")
            checked += 1
        if checked < 3:
            fail(f"{checked} field snapshots from t = {FIRST_CHECKED} s, expected at least 3")
    print("PASS")


if __name__ == "__main__":
    main()
