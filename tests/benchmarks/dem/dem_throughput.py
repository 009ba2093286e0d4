#!/usr/bin/env python3
"""Benchmark: throughput of `parcelflow dem` vs the stock `liggghts` binary on the dry Goldschmidt bed.

Settles the 33,689-bead bed once (not timed), then times the same DEM steps from the same restart with
both programs, alternating them (stock, parcelflow, stock, parcelflow, ...) so that machine noise hits
both alike. Throughput is particle-steps per second from LIGGGHTS' own 'Loop time' line. Prints the
numbers and the ratio; in-process running should cost nothing (ratio 1.00 within noise).
"""
import argparse
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import liggghts_loop, run  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def throughput(output):
    seconds, steps, atoms = liggghts_loop(output)
    return steps * atoms / seconds


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--parcelflow", required=True)
    parser.add_argument("--liggghts", default="liggghts")
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--settle-steps", type=int, default=16000)
    parser.add_argument("--steps", type=int, default=2000)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--mpiexec", nargs=argparse.REMAINDER, default=["mpirun"])
    args = parser.parse_args()
    launch = args.mpiexec + ["-np", str(args.ranks)]
    with tempfile.TemporaryDirectory() as tmp:
        for name in ("goldschmidt_dry_contacts.in", "goldschmidt_dry_settle.in", "goldschmidt_dry_time.in"):
            with open(os.path.join(HERE, name)) as src, open(os.path.join(tmp, name), "w") as dst:
                dst.write(src.read())
        print(f"settling 33,689 beads for {args.settle_steps} steps ...", flush=True)
        run(launch + [args.parcelflow, "dem", "goldschmidt_dry_settle.in", "-var", "settle_steps",
                      str(args.settle_steps), "-var", "restart", "settled.restart"], tmp)
        timing = ["goldschmidt_dry_time.in", "-var", "restart", "settled.restart", "-var", "steps", str(args.steps)]
        rates = {"liggghts": [], "parcelflow dem": []}
        for r in range(args.repeats):
            rates["liggghts"].append(throughput(run(launch + [args.liggghts, "-in"] + timing, tmp)))
            rates["parcelflow dem"].append(throughput(run(launch + [args.parcelflow, "dem"] + timing, tmp)))
            print(f"round {r + 1}: liggghts {rates['liggghts'][-1]:.4g}, parcelflow dem "
                  f"{rates['parcelflow dem'][-1]:.4g} particle-steps/s", flush=True)
    ratios = [p / s for p, s in zip(rates["parcelflow dem"], rates["liggghts"])]
    for name, values in rates.items():
        print(f"{name:15s} median {statistics.median(values):.4g} particle-steps/s on {args.ranks} rank(s) "
              f"(min {min(values):.4g}, max {max(values):.4g})")
    print(f"ratio parcelflow dem / liggghts: median {statistics.median(ratios):.3f} "
          f"(per round: {', '.join(f'{x:.3f}' for x in ratios)})")


if __name__ == "__main__":
    main()
