#!/usr/bin/env python3
"""Benchmark: wall time of the coupled loop against pure LIGGGHTS on the same parcels and DEM steps.

Runs cases/fluidized_column coupled for --time seconds, then the same LIGGGHTS script (same insertion and
settling) through `parcelflow dem` followed by the same number of DEM steps without gas, back to back on
the same ranks. Coupled time: the loop's own wall time from parcelflow's summary line (settling excluded);
pure time: LIGGGHTS' 'Loop time' of the final run. Prints both, their ratio and the coupled split.
"""
import argparse
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, copy_case, loop_timing, run  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--parcelflow", required=True)
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--time", type=float, default=0.2)
    parser.add_argument("--mpiexec", nargs=argparse.REMAINDER, default=["mpirun"])
    args = parser.parse_args()
    launch = args.mpiexec + ["-np", str(args.ranks)]
    with tempfile.TemporaryDirectory() as tmp:
        settings = {}

        def edit(case_settings):
            case_settings["time"]["end"] = args.time
            settings.update(case_settings)

        case = copy_case(os.path.join(CASES, "fluidized_column"), tmp, edit)
        coupled = run(launch + [args.parcelflow, "run", case, "--output", os.path.join(tmp, "out")], tmp)
        wall, split = loop_timing(coupled)
        t = settings["time"]
        steps = round(args.time / t["dem_step"])
        variables = dict(settings["liggghts"]["variables"], dem_step=repr(t["dem_step"]))
        with open(os.path.join(case, "in.pure"), "w") as f:
            f.write(f"include {settings['liggghts']['script']}\nrun {steps}\n")
        command = launch + [args.parcelflow, "dem", "in.pure"]
        for name, value in variables.items():
            command += ["-var", name, str(value)]
        pure_out = run(command, case)
        seconds, atoms = re.findall(r"Loop time of ([0-9.eE+-]+) on \d+ procs for \d+ steps with (\d+) atoms", pure_out)[-1]
        pure = float(seconds)
    print(f"{atoms} parcels, {steps} DEM steps on {args.ranks} rank(s): coupled loop {wall:.1f} s, pure LIGGGHTS "
          f"{pure:.1f} s, ratio {wall / pure:.2f}; coupled {int(atoms) * steps / wall:.3g} parcel-steps/s")
    print(f"coupled split: {split}")


if __name__ == "__main__":
    main()
