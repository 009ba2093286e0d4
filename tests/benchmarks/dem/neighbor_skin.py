#!/usr/bin/python3
"""Benchmark: LIGGGHTS' neighbour-list skin of a case, measured on one fluidized bed state (issue 30, part 3).

Runs the case coupled to --establish seconds and writes a checkpoint there (or takes --checkpoint), then runs
the checkpoint's LIGGGHTS restart in pure LIGGGHTS (`parcelflow dem`, the case's own script, as same_state.py
does: the parcels keep their last gas forces, so the bed stays fluidized) for --steps DEM steps once per skin,
round after round (skin A, B, C, A, B, C, ...) so that the machine's drift hits every skin alike. The skin is
set after the script (`neighbor SKIN bin`, rebuilds checked every step), so the contacts and the trajectories
are the same for every skin: only the cost of finding them changes. Prints per skin LIGGGHTS' loop time
(median and range over the rounds), its neighbour-list builds and the share of the loop they take, and each
round's time against the first skin's of the same round.
"""
import argparse
import os
import re
import shutil
import statistics
import sys
import tempfile

import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, dem_restart_command, establish_checkpoint, liggghts_loop, run  # noqa: E402

BUILDS = re.compile(r"Neighbor list builds = (\d+)")
NEIGH_SHARE = re.compile(r"^Neigh time \(%\) = [0-9.eE+-]+ \(([0-9.eE+-]+)\)", re.MULTILINE)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--parcelflow", required=True)
    parser.add_argument("--case", default="goldschmidt_segregation", help="a folder of cases/ or a case folder")
    parser.add_argument("--checkpoint", help="a checkpoint of a run of --case instead of establishing one")
    parser.add_argument("--establish", type=float, default=0.5, help="simulated time to the measured state [s]")
    parser.add_argument("--steps", type=int, default=2400, help="DEM steps per run")
    parser.add_argument("--skins", type=float, nargs="+", default=[0.001, 0.0005, 0.00075, 0.0015],
                        help="skins [m]; the first (the Goldschmidt case's) is the reference of the per-round ratios")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--mpiexec", nargs=argparse.REMAINDER, default=["mpirun"])
    args = parser.parse_args()
    launch = args.mpiexec + ["-np", str(args.ranks)]
    source = args.case if os.path.isdir(args.case) else os.path.join(CASES, args.case)
    with tempfile.TemporaryDirectory() as tmp:
        if args.checkpoint:
            case = os.path.join(tmp, "case")
            shutil.copytree(source, case, ignore=shutil.ignore_patterns("output"))
            checkpoint = os.path.abspath(args.checkpoint)
        else:
            case, checkpoint = establish_checkpoint(args.parcelflow, launch, source, tmp, args.establish)
        settings = yaml.safe_load(open(os.path.join(case, "case.yaml")))
        times = {skin: [] for skin in args.skins}
        builds, shares = {}, {skin: [] for skin in args.skins}
        for _ in range(args.rounds):
            for skin in args.skins:
                with open(os.path.join(case, "in.skin"), "w") as f:
                    f.write(f"include {settings['liggghts']['script']}\nneighbor {skin!r} bin\n"
                            f"neigh_modify every 1 delay 0 check yes\nrun 0 post no\nrun {args.steps}\n")
                command = dem_restart_command(launch, args.parcelflow, "in.skin", settings, checkpoint, "none")
                output = run(command, case)
                seconds, _, atoms = liggghts_loop(output)
                times[skin].append(seconds)
                builds[skin] = int(BUILDS.findall(output)[-1])
                share = NEIGH_SHARE.findall(output)
                if share:
                    shares[skin].append(float(share[-1]))
        print(f"{os.path.basename(source)}: {atoms} parcels, {args.steps} DEM steps from {checkpoint} on {args.ranks} "
              f"rank(s), {args.rounds} rounds")
        for skin in args.skins:
            t = times[skin]
            share = f", neighbour share {statistics.median(shares[skin]):.1f} %" if shares[skin] else ""
            print(f"skin {skin * 1e3:.3g} mm: loop {statistics.median(t):.2f} s (min {min(t):.2f}, max {max(t):.2f}), "
                  f"{builds[skin]} neighbour-list builds (every {args.steps / max(builds[skin], 1):.1f} steps){share}; "
                  f"per round {', '.join(f'{x:.2f}' for x in t)} s, against skin {args.skins[0] * 1e3:.3g} mm "
                  f"{', '.join(f'{x / y:.3f}' for x, y in zip(t, times[args.skins[0]]))}")


if __name__ == "__main__":
    main()
