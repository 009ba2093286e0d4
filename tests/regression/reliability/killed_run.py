"""A run killed with SIGKILL (mpirun and every rank at once, no handler runs) while it writes every output
every few steps, three times at different moments: monitors.csv holds only complete rows, every HDF5 file in
the output folder opens with h5py (a file is written as NAME.partial and renamed once complete), every file
an XDMF index lists exists and opens, the complete checkpoints are readable, and the run continues from the
newest of them. It runs with the named semaphore that Open MPI's OMPIO takes to open a file called
gas.h5.partial present and taken, as a killed run leaves it: no run may wait on it (cfd/io/mpi_io_defaults.hpp)."""
import ctypes
import errno
import glob
import os
import subprocess
import sys
import time

import h5py

from disk_full import check_csv, check_hdf5
from reliability_runs import GAS_STEP, Runs, expect, fail

EVERY = {"monitor_interval": GAS_STEP, "fields_interval": GAS_STEP, "parcels_interval": GAS_STEP,
         "checkpoint_interval": 7 * GAS_STEP}


def kill_after(runs, case, out, rows):
    """Starts the run and kills it with SIGKILL once monitors.csv has `rows` rows."""
    command = runs.launcher + [runs.parcelflow, "run", case, "--output", out, "--end", repr(2000 * GAS_STEP)]
    job = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=runs.env)
    csv = os.path.join(out, "monitors.csv")
    deadline = time.time() + 120
    while job.poll() is None:
        if os.path.exists(csv) and sum(1 for _ in open(csv)) > rows:
            break
        if time.time() > deadline:
            subprocess.run(["pkill", "-KILL", "-f", out])
            fail(f"the run did not write {rows} monitor rows within 120 s (it hangs)")
        time.sleep(0.05)
    if job.poll() is not None:
        fail(f"the run ended (exit code {job.returncode}) before it was killed")
    subprocess.run(["pkill", "-KILL", "-f", out])  # mpirun and the ranks: each names the output folder
    job.wait(timeout=60)
    deadline = time.time() + 30  # a rank may outlive mpirun briefly; look at the output only when all are gone
    while subprocess.run(["pgrep", "-f", out], stdout=subprocess.DEVNULL).returncode == 0:
        if time.time() > deadline:
            fail(f"a process naming {out} is still alive 30 s after SIGKILL")
        subprocess.run(["pkill", "-KILL", "-f", out])
        time.sleep(0.1)


def killed(runs, rows):
    case = runs.case(lambda s: s["output"].update(EVERY))
    out = os.path.join(os.path.dirname(case), "output")
    kill_after(runs, case, out, rows)
    complete = check_csv(out)
    listed, checkpoints = check_hdf5(out)
    present = glob.glob(os.path.join(out, "*.h5"))
    for path in present:
        try:
            with h5py.File(path, "r") as f:
                list(f.keys())
        except OSError as e:
            fail(f"killed after {rows} rows: {os.path.basename(path)} does not open: {e}")
    partial = [os.path.basename(p) for p in glob.glob(os.path.join(out, "*.partial"))]
    if not checkpoints:
        fail(f"killed after {rows} rows: no complete checkpoint")
    print(f"[measured] killed after {rows} rows: {complete} complete monitor rows, {len(present)} HDF5 files open "
          f"({len(listed)} listed), unfinished {partial or 'none'}, checkpoints "
          f"{[os.path.basename(c) for c in checkpoints]}")
    step = int(os.path.basename(checkpoints[-1]).split("_")[1])
    expect(f"continued from {os.path.basename(checkpoints[-1])}",
           runs.run(case, "--restart", checkpoints[-1], output=out, end=(step + 5) * GAS_STEP), 0, "done:")


def taken_ompio_semaphore():
    """Creates /dev/shm/sem.OMPIO_gas.h5.partial with value 0 unless it exists; returns an undo function."""
    libc = ctypes.CDLL(None, use_errno=True)
    libc.sem_open.restype = ctypes.c_void_p
    name = b"/OMPIO_gas.h5.partial"
    if libc.sem_open(name, os.O_CREAT | os.O_EXCL, 0o644, 0) is not None:  # SEM_FAILED is NULL in glibc
        return lambda: libc.sem_unlink(name)
    if ctypes.get_errno() != errno.EEXIST:  # without it the test would not test the hang
        fail(f"cannot create the semaphore {name.decode()}: {os.strerror(ctypes.get_errno())}")
    return lambda: None


def main():
    runs = Runs(sys.argv)
    undo = taken_ompio_semaphore()
    try:
        for rows in (15, 32, 49):
            killed(runs, rows)
    finally:
        undo()
        runs.close()
    print("PASS")


if __name__ == "__main__":
    main()
