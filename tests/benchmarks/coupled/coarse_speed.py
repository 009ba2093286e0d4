#!/usr/bin/python3
"""Benchmark: how much faster a coarse-grained Goldschmidt bed runs than the fine one, per simulated second, on
the same ranks, under each stopping criterion of the linear solves (issue 30's aim: np 8 at least 6 times).

1. cases/goldschmidt_segregation/coarse_graining.py makes each variant's bed (fine and np 8 by default: the same
   beads, the same solid mass) and runs it coupled to --establish seconds (the bed bubbling), writing a
   checkpoint there.
2. For each round, each variant and each criterion in turn, the checkpoint is continued for --span seconds with
   `solver.pressure.criterion` and `solver.momentum.criterion` set to the criterion (a restart may change
   solver.*): the loop's wall time (LIGGGHTS' start-up excluded) per simulated second, its DEM / coupling / gas
   split, and the mean pressure iterations per gas step from monitors.csv.
Prints every run and, per criterion, each coarse variant's speed-up over the fine bed, round by round (the
runs of one round are back to back, so the ratios compare like with like).

usage: coarse_speed.py --parcelflow P [--variants fine np8_linear] [--establish 0.5] [--span 1.0] [--rounds 1]
                       [--ranks 2] [--criteria strict normalized] [--mpiexec mpirun ...]
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "support"))
from parcelflow_runs import CASES, loop_timing, run  # noqa: E402

COARSE_GRAINING = os.path.join(CASES, "goldschmidt_segregation", "coarse_graining.py")


def establish(args, launch, root):
    """Each variant's run to --establish with a checkpoint there: {variant: (case folder, checkpoint folder)}."""
    command = [sys.executable, COARSE_GRAINING, args.parcelflow, root, *args.variants, "--end", repr(args.establish),
               "--start", "0", "--ranks", str(args.ranks), "--mpirun", " ".join(launch[:-2]),
               "--set", f"output.checkpoint_interval={args.establish!r}", "--set", "output.fields_interval=0"]
    if subprocess.run(command, stdout=subprocess.DEVNULL).returncode != 0:
        sys.exit("coarse_graining.py failed to establish the beds (rerun it alone to see why)")
    states = {}
    for variant in args.variants:
        folder = os.path.join(root, variant, "run", "checkpoints")
        states[variant] = (os.path.join(root, variant, "case"), os.path.join(folder, sorted(os.listdir(folder))[-1]))
    return states


def continue_run(args, launch, work, case, checkpoint, criterion):
    """(loop wall time per simulated second, split, pressure iterations per gas step) of --span seconds from the
    checkpoint under the criterion."""
    shutil.rmtree(work, ignore_errors=True)
    edited = os.path.join(work, "case")
    shutil.copytree(case, edited)
    with open(os.path.join(edited, "case.yaml")) as f:
        settings = yaml.safe_load(f)
    settings["solver"] = {"pressure": {"criterion": criterion}, "momentum": {"criterion": criterion}}
    with open(os.path.join(edited, "case.yaml"), "w") as f:
        yaml.safe_dump(settings, f, sort_keys=False)
    out = os.path.join(work, "out")
    shutil.copytree(os.path.join(checkpoint, "..", ".."), out, ignore=shutil.ignore_patterns("checkpoints"))
    with open(os.path.join(checkpoint, "loop.yaml")) as f:
        start = float(yaml.safe_load(f)["loop"]["time"])
    stdout = run(launch + [args.parcelflow, "run", edited, "--output", out, "--end", repr(start + args.span),
                           "--restart", checkpoint], work)
    wall, split = loop_timing(stdout)
    with open(os.path.join(out, "monitors.csv")) as f:
        iterations = [float(r["pressure_iterations"]) for r in csv.DictReader(f) if float(r["time"]) > start + 1e-9]
    return wall / args.span, split, sum(iterations) / len(iterations)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--parcelflow", required=True)
    p.add_argument("--variants", nargs="+", default=["fine", "np8_linear"], help="coarse_graining.py's; fine first")
    p.add_argument("--establish", type=float, default=0.5)
    p.add_argument("--span", type=float, default=1.0)
    p.add_argument("--rounds", type=int, default=1)
    p.add_argument("--ranks", type=int, default=2)
    p.add_argument("--criteria", nargs="+", default=["strict", "normalized"])
    p.add_argument("--mpiexec", nargs=argparse.REMAINDER, default=["mpirun"])
    args = p.parse_args()
    if args.variants[0] != "fine":
        sys.exit(f"--variants {' '.join(args.variants)}: the first must be fine (the others are compared with it)")
    args.parcelflow = os.path.abspath(args.parcelflow)
    launch = args.mpiexec + ["-np", str(args.ranks)]
    with tempfile.TemporaryDirectory(prefix="pf_coarse_speed_") as tmp:
        states = establish(args, launch, os.path.join(tmp, "beds"))
        print(f"from t = {args.establish:g} s, {args.span:g} s each on {args.ranks} rank(s)")
        for round_ in range(1, args.rounds + 1):
            speed = {}
            for variant in args.variants:
                for criterion in args.criteria:
                    case, checkpoint = states[variant]
                    per_second, split, iterations = continue_run(args, launch, os.path.join(tmp, "run"), case,
                                                                 checkpoint, criterion)
                    speed[variant, criterion] = per_second
                    print(f"round {round_} {variant:14s} {criterion:10s} {per_second:8.1f} s of loop per simulated "
                          f"second, {iterations:5.1f} pressure iterations per gas step; {split}", flush=True)
            for criterion in args.criteria:
                for variant in args.variants[1:]:
                    ratio = speed["fine", criterion] / speed[variant, criterion]
                    print(f"round {round_} {criterion:10s} {variant} runs {ratio:.2f} times as fast as fine", flush=True)


if __name__ == "__main__":
    main()
