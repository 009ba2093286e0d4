#!/usr/bin/python3
"""Benchmark: the coupled loop against pure LIGGGHTS from the same bed state, for the same DEM steps.

1. Runs a case coupled until --establish seconds (the bed fluidized) and writes a checkpoint there.
2. Continues that checkpoint coupled for --steps gas steps: the loop's wall time from parcelflow's summary
   line (LIGGGHTS' start-up excluded) and its DEM / coupling / gas / output split.
3. Runs the checkpoint's LIGGGHTS restart in pure LIGGGHTS (`parcelflow dem`, the case's own script, which reads
   the restart) for the same number of DEM steps: the same parcels and contacts, with the last gas forces held
   fixed by fix parcel/implicit_drag (kappa, u_f and f_p are in the restart), so the bed stays fluidized. Its
   time is LIGGGHTS' 'Loop time'.
Both on the same ranks, back to back. Prints both times, their ratio, the split, parcel-steps per second,
the coupled run's peak memory per rank and, on more than one rank, each phase's time on the fastest and the
slowest rank.
With --checkpoint (a checkpoint of a run of --case, a folder path; for beds whose settling and establishing
take hours, such as the full FCC bed) step 1 is skipped: the measured state is that checkpoint's.
"""
import argparse
import os
import shutil
import sys
import tempfile

import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import (CASES, dem_restart_command, establish_checkpoint, liggghts_loop,  # noqa: E402
                             loop_timing, run)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--parcelflow", required=True)
    parser.add_argument("--case", default="fluidized_column", help="a folder of cases/ or a case folder's path")
    parser.add_argument("--checkpoint", help="start from this checkpoint of a run of --case instead of establishing")
    parser.add_argument("--establish", type=float, default=0.2, help="simulated time to the measured state [s]")
    parser.add_argument("--steps", type=int, default=1000, help="gas steps measured")
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--mpiexec", nargs=argparse.REMAINDER, default=["mpirun"])
    args = parser.parse_args()
    launch = args.mpiexec + ["-np", str(args.ranks)]
    with tempfile.TemporaryDirectory() as tmp:
        source = args.case if os.path.isdir(args.case) else os.path.join(CASES, args.case)
        out = os.path.join(tmp, "out")
        if args.checkpoint:
            # unedited: a restart refuses settings that differ, even in how a number is written
            case = os.path.join(tmp, "case")
            shutil.copytree(source, case, ignore=shutil.ignore_patterns("output"))
            checkpoint = os.path.abspath(args.checkpoint)
            args.establish = float(yaml.safe_load(open(os.path.join(checkpoint, "loop.yaml")))["loop"]["time"])
            # a continued run appends to the series of the run that wrote the checkpoint (monitors.csv, the
            # parcel and field files): its output folder without the checkpoints
            shutil.copytree(os.path.join(checkpoint, "..", ".."), out, ignore=shutil.ignore_patterns("checkpoints"))
        else:
            case, checkpoint = establish_checkpoint(args.parcelflow, launch, source, tmp, args.establish)
        settings = yaml.safe_load(open(os.path.join(case, "case.yaml")))
        t = settings["time"]
        dem_per_gas = round(t["gas_step"] / t["dem_step"])
        end = args.establish + args.steps * t["gas_step"]
        coupled = run(launch + [args.parcelflow, "run", case, "--output", out, "--end", repr(end),
                                "--restart", checkpoint], tmp)
        wall, split = loop_timing(coupled)
        steps = args.steps * dem_per_gas
        with open(os.path.join(case, "in.pure"), "w") as f:
            f.write(f"include {settings['liggghts']['script']}\nrun 0 post no\nrun {steps}\n")
        command = dem_restart_command(launch, args.parcelflow, "in.pure", settings, checkpoint,
                                      os.path.join(tmp, "log.pure"))
        pure_out = run(command, case)
        pure, _, parcels = liggghts_loop(pure_out)
    print(f"{args.case}: {parcels} parcels, {steps} DEM steps ({args.steps} gas steps) from t = {args.establish} s on "
          f"{args.ranks} rank(s): coupled loop {wall:.2f} s, pure LIGGGHTS {pure:.2f} s, ratio {wall / pure:.3f}; "
          f"coupled {parcels * steps / wall:.3g}, pure {parcels * steps / pure:.3g} parcel-steps/s")
    print(f"coupled split: {split}")
    for start in ("parcelflow: peak memory per rank", "parcelflow: wall time per phase"):
        lines = [line for line in coupled.splitlines() if line.startswith(start)]
        if lines:
            print(f"coupled {lines[-1][len('parcelflow: '):]}")


if __name__ == "__main__":
    main()
