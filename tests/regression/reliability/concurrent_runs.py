"""Two runs into one output folder at the same time (the second used to move the first's monitors.csv and
snapshots into earlier_run_1/ while the first wrote them): the second stops before any work, with exit code 2
and a message naming --output, the folder, the first run's pid and what is allowed; the first run's
monitors.csv stays where it is, grows on and ends with every row complete. Once the first run has ended (here
stopped by SIGTERM to the pid the message names, after a checkpoint), a run continues it in the same folder
with --restart."""
import csv
import os
import re
import signal
import subprocess
import time

from disk_full import check_csv
from reliability_runs import GAS_STEP, expect, fail, main


def monitor_times(out):
    with open(os.path.join(out, "monitors.csv")) as f:
        return [float(row["time"]) for row in csv.DictReader(f)]


def second_run_while_the_first_writes(runs):
    case = runs.case(lambda s: s["output"].update({"monitor_interval": GAS_STEP, "checkpoint_interval": 0}))
    out = os.path.join(os.path.dirname(case), "output")
    monitors = os.path.join(out, "monitors.csv")
    log = open(os.path.join(runs.work, "first_run.log"), "w+")
    first = subprocess.Popen(runs.launcher + [runs.parcelflow, "run", case, "--output", out, "--end",
                                              repr(100000 * GAS_STEP)], stdout=log, stderr=subprocess.STDOUT,
                             env=runs.env)
    try:
        deadline = time.time() + 120
        while not (os.path.exists(monitors) and len(open(monitors).read().splitlines()) > 3):
            if first.poll() is not None or time.time() > deadline:
                log.seek(0)
                fail(f"the first run wrote no monitor rows (exit code {first.poll()})\n{log.read()[-3000:]}")
            time.sleep(0.05)
        before = open(monitors, "rb").read()

        text = expect("a second run into the first's folder", runs.run(case, output=out), 2,
                      f"--output = {out} (another parcelflow run, pid ", "is writing there)",
                      "allowed is a folder no other run is writing to: give another one, or wait until that run "
                      "has ended")
        if first.poll() is not None:
            fail(f"the first run ended (exit code {first.returncode}) before the second was refused: the test "
                 "did not overlap them")
        if "LIGGGHTS (" in text or "earlier run" in text:
            fail(f"the second run started work before it was refused:\n{text[-3000:]}")
        aside = [name for name in os.listdir(out) if name.startswith("earlier_run_")]
        if aside:
            fail(f"the second run moved the first's output aside into {aside}")
        pid = int(re.search(r"another parcelflow run, pid ([0-9]+) on host ", text).group(1))
        if out not in open(f"/proc/{pid}/cmdline").read().replace("\0", " "):
            fail(f"pid {pid} named by the message is not the first run")
        os.kill(pid, signal.SIGTERM)  # the first run's rank 0: the run stops after a checkpoint
        first.wait(timeout=300)
    finally:
        if first.poll() is None:  # the test failed: end mpirun and its ranks
            ranks = subprocess.run(["pgrep", "-P", str(first.pid)], capture_output=True, text=True).stdout.split()
            for rank in ranks:
                os.kill(int(rank), signal.SIGKILL)
            first.kill()
            first.wait()
    log.seek(0)
    first_text = log.read()
    log.close()
    if "stopped by signal 15 after a checkpoint" not in first_text:
        fail(f"the first run did not stop after a checkpoint (exit code {first.returncode})\n{first_text[-3000:]}")

    rows = check_csv(out)
    after = open(monitors, "rb").read()
    times = monitor_times(out)
    expected = [GAS_STEP * (k + 1) for k in range(rows)]
    if not after.startswith(before) or any(abs(t - e) > 1e-3 * GAS_STEP for t, e in zip(times, expected)):
        fail(f"the first run's monitors.csv is not one complete series: times {times[:5]}...{times[-3:]}")
    print(f"[measured] the first run's monitors.csv: {len(before.splitlines()) - 1} rows when the second run was "
          f"refused, {rows} complete consecutive rows at its end")

    checkpoint = first_text.split("--restart")[-1].split()[0]
    step = int(os.path.basename(checkpoint).split("_")[1])
    expect("continued in the same folder after the first run ended",
           runs.run(case, "--restart", checkpoint, output=out, end=(step + 5) * GAS_STEP), 0, "done:")
    if len(monitor_times(out)) != step + 5:
        fail(f"after continuing: {len(monitor_times(out))} monitor rows, expected {step + 5}")


if __name__ == "__main__":
    main([second_run_while_the_first_writes])
