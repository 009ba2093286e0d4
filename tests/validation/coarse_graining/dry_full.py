#!/usr/bin/env python3
"""The full dry coarse-graining validation (cases/coarse_graining/dry/validate.py --size full --seeds 3
--coarse-seeds 8 --require-pass, the README's table) in a temporary folder: fails when a row that its
scaling claims within the parcels' geometric limits is outside the 5 % tolerance (5 rows, all within it on
2026-12-04: README.md of the case). About 50 minutes on one core of the shared 2-core machine.

usage: dry_full.py PARCELFLOW LIGGGHTS MPIEXEC...
"""
import os
import shlex
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, fail  # noqa: E402

DRIVER = os.path.join(CASES, "coarse_graining", "dry", "validate.py")


def main():
    parcelflow, liggghts, launcher = sys.argv[1], sys.argv[2], sys.argv[3:]
    with tempfile.TemporaryDirectory(prefix="pf_cg_dry_full_") as work:
        done = subprocess.run([sys.executable, DRIVER, "--size", "full", "--seeds", "3", "--coarse-seeds", "8",
                               "--runs", work, "--require-pass",
                               "--parcelflow", parcelflow, "--liggghts", liggghts, "--mpirun", shlex.join(launcher)])
    if done.returncode != 0:
        fail(f"validate.py --size full --require-pass exited with {done.returncode} (table above)")
    print("PASS")


if __name__ == "__main__":
    main()
