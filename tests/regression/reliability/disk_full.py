"""A disk that fills (a 2 MB tmpfs as the output folder; skipped with exit code 77 where mounting is not
allowed): the run stops with a non-zero exit code and a message naming the file, monitors.csv keeps only
complete rows, every HDF5 file an XDMF index lists opens with h5py, and the newest complete checkpoint is
readable. First with only monitors.csv (and LIGGGHTS' log) growing into the last 512 kB, then with every
output due every few steps."""
import glob
import os
import re
import subprocess
import sys

import h5py

from reliability_runs import GAS_STEP, Runs, expect, fail


def mount(folder):
    os.makedirs(folder)
    done = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=2m", "tmpfs", folder], capture_output=True, text=True)
    return done.returncode == 0


def check_csv(out):
    lines = open(os.path.join(out, "monitors.csv")).read().split("\n")
    if lines[-1] != "":
        fail("monitors.csv ends with a partial row")
    width = len(lines[0].split(","))
    rows = [l.split(",") for l in lines[1:-1]]
    if any(len(r) != width for r in rows):
        fail("monitors.csv has a row with missing columns")
    [float(v) for r in rows for v in r]
    return len(rows)


def check_hdf5(out):
    listed = []
    for index in glob.glob(os.path.join(out, "*.xdmf")):
        listed += sorted(set(re.findall(r"([a-z_]+[0-9]*\.h5):", open(index).read())))
    for name in listed:
        with h5py.File(os.path.join(out, name), "r") as f:
            list(f.keys())
    checkpoints = sorted(glob.glob(os.path.join(out, "checkpoints", "step_*")))
    for folder in checkpoints:
        with h5py.File(os.path.join(folder, "gas.h5"), "r") as f:
            list(f.keys())
        if not os.path.getsize(os.path.join(folder, "loop.yaml")):
            fail(f"{folder}/loop.yaml is empty")
    return listed, checkpoints


def monitors_only(runs, disk):
    out = os.path.join(disk, "monitors_only")
    os.makedirs(out)
    with open(os.path.join(disk, "filler"), "wb") as filler:
        filler.write(b"\0" * (2 * 1024 * 1024 - 512 * 1024))
    case = runs.case(lambda s: s["output"].update(monitor_interval=GAS_STEP))
    text = expect("monitors.csv on a full disk", runs.run(case, end=2000 * GAS_STEP, output=out), None,
                  "writing '" + os.path.join(out, "monitors.csv") + "' failed: No space left on device",
                  "complete rows")
    rows = check_csv(out)
    if "parcelflow: done" in text or rows >= 2000:
        fail(f"the run went on after the failed write ({rows} rows)")
    print(f"[measured] monitors.csv kept {rows} complete rows")
    os.remove(os.path.join(disk, "filler"))


def every_output(runs, disk):
    out = os.path.join(disk, "every_output")
    every = {"monitor_interval": GAS_STEP, "fields_interval": 2 * GAS_STEP, "parcels_interval": 2 * GAS_STEP,
             "checkpoint_interval": 5 * GAS_STEP}
    case = runs.case(lambda s: s["output"].update(every))
    rc, text, _ = runs.run(case, end=1000 * GAS_STEP, output=out)
    message = next((l for l in text.splitlines() if l.startswith("parcelflow: rank") and out in l), None)
    if rc == 0 or message is None:
        fail(f"a full disk must stop the run with a message naming the file (exit code {rc})\n{text[-3000:]}")
    rows = check_csv(out)
    listed, checkpoints = check_hdf5(out)
    if not checkpoints or len(listed) < 3:
        fail(f"expected snapshots and a checkpoint before the disk filled: {listed}, {checkpoints}")
    print(f"[measured] stopped with exit code {rc}: {message.strip()[:300]}")
    print(f"[measured] {rows} complete monitor rows, {len(listed)} HDF5 files listed and readable, checkpoints "
          f"{[os.path.basename(c) for c in checkpoints]} readable")


def main():
    if os.geteuid() != 0:
        print("SKIP: mounting a tmpfs needs root")
        sys.exit(77)
    runs = Runs(sys.argv)
    disk = os.path.join(runs.work, "disk")
    try:
        if not mount(disk):
            print("SKIP: mount -t tmpfs is not allowed here")
            sys.exit(77)
        try:
            monitors_only(runs, disk)
            every_output(runs, disk)
        finally:
            subprocess.run(["umount", disk])
    finally:
        runs.close()
    print("PASS")


if __name__ == "__main__":
    main()
