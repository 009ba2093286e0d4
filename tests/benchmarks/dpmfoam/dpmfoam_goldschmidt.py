#!/usr/bin/python3
"""Benchmark: cases/openfoam_dpmfoam_goldschmidt in parcelflow and, where OpenFOAM is installed, the same bed
in DPMFoam (its tutorial lagrangian/DPMFoam/Goldschmidt), for the same simulated time from t = 0.

parcelflow: the coupled loop's own wall time from its summary line (LIGGGHTS set-up excluded), as wall
seconds per simulated second and parcel-steps per second (parcels x DEM steps / wall).
DPMFoam: the tutorial copied from Debian's openfoam-examples, blockMesh, then DPMFoam in serial with
endTime set to the same simulated time; its time per step is the difference of its ExecutionTime between
the first and the last step over the steps between them (set-up and the first step excluded).
Both start from the tutorial's lattice of falling beads, so the first milliseconds have few contacts.

usage: dpmfoam_goldschmidt.py --parcelflow BIN [--ranks N] [--time SECONDS] [--mpiexec MPIEXEC ...]
"""
import argparse
import glob
import gzip
import os
import re
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, copy_case, fail, loop_timing, run  # noqa: E402

TUTORIAL = "/usr/share/doc/openfoam-examples/examples/lagrangian/DPMFoam/Goldschmidt"
OPENFOAM_BASHRC = "/usr/share/openfoam/etc/bashrc"
PARCELS, GAS_STEP = 24750, 2e-5


def run_parcelflow(args, work):
    settings = {}

    def edit(case):
        case["time"]["end"] = args.time
        settings.update(case)

    case = copy_case(os.path.join(CASES, "openfoam_dpmfoam_goldschmidt"), work, edit)
    launch = args.mpiexec + ["-np", str(args.ranks)]
    out = run(launch + [args.parcelflow, "run", case, "--output", os.path.join(work, "out")], work)
    wall, split = loop_timing(out)
    return wall, round(args.time / settings["time"]["dem_step"]), split


def copy_tutorial(work, end_time):
    case = os.path.join(work, "dpmfoam")
    shutil.copytree(TUTORIAL, case)
    for packed in glob.glob(os.path.join(case, "**", "*.gz"), recursive=True):
        with gzip.open(packed, "rb") as source, open(packed[:-3], "wb") as target:
            shutil.copyfileobj(source, target)
        os.remove(packed)
    control = os.path.join(case, "system", "controlDict")
    text = re.sub(r"^endTime\s+[^;]+;", f"endTime         {end_time!r};", open(control).read(), flags=re.M)
    open(control, "w").write(text)
    return case


def run_dpmfoam(args, work):
    """Seconds per DPMFoam step (ExecutionTime differences) and the number of steps."""
    case = copy_tutorial(work, args.time)
    for program in ("blockMesh", "DPMFoam"):
        out = run(["bash", "-c", f"source {OPENFOAM_BASHRC} >/dev/null 2>&1; {program}"], case)
    times = [float(t) for t in re.findall(r"^ExecutionTime = ([0-9.eE+-]+) s", out, flags=re.M)]
    if len(times) < 3:
        fail(f"DPMFoam printed {len(times)} time steps; increase --time")
    return (times[-1] - times[0]) / (len(times) - 1), len(times)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--parcelflow", required=True)
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--time", type=float, default=0.03, help="simulated seconds from t = 0 (0.03: the bed has landed)")
    parser.add_argument("--mpiexec", nargs=argparse.REMAINDER, default=["mpirun"])
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        wall, dem_steps, split = run_parcelflow(args, work)
        per_second = wall / args.time
        print(f"parcelflow on {args.ranks} rank(s): {args.time} s simulated ({round(args.time / GAS_STEP)} gas steps, "
              f"{dem_steps} DEM steps) in {wall:.1f} s: {per_second / 3600:.2f} h per simulated second, "
              f"{PARCELS * dem_steps / wall:.3g} parcel-steps/s; {split}")
        if not (shutil.which("DPMFoam") and os.path.isdir(TUTORIAL) and os.path.isfile(OPENFOAM_BASHRC)):
            print("DPMFoam: not installed (Debian packages openfoam and openfoam-examples); no ratio")
            return
        step, steps = run_dpmfoam(args, work)
        dpmfoam_per_second = step / GAS_STEP
        print(f"DPMFoam on 1 core: {steps} steps, {step:.3f} s per step (CPU time of steps 2..{steps}): "
              f"{dpmfoam_per_second / 3600:.2f} h per simulated second")
        print(f"ratio DPMFoam / parcelflow (wall per simulated second): {dpmfoam_per_second / per_second:.2f}")


if __name__ == "__main__":
    main()
