"""Checkpoint and restart of a coupled run (cases/fluidized_column, N = 50 gas steps).

  same_ranks R:   run A for 2N steps (checkpoints every N); run B for N steps, restart, N more, on R ranks.
                  B's monitors.csv has A's rows, none twice or missing; every monitor value and the last
                  field snapshot equal A's exactly, and the first gas step after the restart takes the same
                  number of pressure iterations. Equality is expected bit for bit: the restart restores every
                  state the next step reads (gas: alpha, p_rgh and its lagged gradient, u, face fluxes; DEM:
                  the LIGGGHTS restart with the forces the next step starts from), and the run that wrote
                  the checkpoint sets up LIGGGHTS and the pressure preconditioner again exactly as the
                  restarted run does. The tolerance below is 1e-12 relative, far below any physical change.
  other_ranks:    B's checkpoint continued on 1 rank instead of 2 (case, output and checkpoint given as relative
                  paths: a relative --restart once failed to open gas.h5 after LIGGGHTS entered the case folder). Only the pressure solve's partition differs
                  (block preconditioner of 1 vs 2 blocks, the same strict tolerance 1e-8 relative, set by edit): monitors agree to
                  1e-6 relative after N steps, set by that tolerance times the N steps' growth.
  refusals:       a case whose drag law differs, a checkpoint with gas.h5 of another checkpoint, a gas.h5 that
                  is not HDF5, a loop.yaml whose time is not its step x gas step and an output folder without
                  the parcel series the checkpoint continues stop with exit code 2 before any step, naming
                  what differs.
  averages:       monitors.average from 0.004 s: the averaged pressures of averages.csv equal the mean of the
                  per-step monitor rows after the start (the same quantity averaged independently; 1e-9, as
                  monitors.csv holds 10 digits), the
                  profile and bed height follow from them as documented, the averaged solids fraction holds the
                  parcels' volume (deposition conserves it: 1e-12), and B's averages equal A's after the restart.
  signal R:       SIGTERM to mpirun (and, with 2 ranks, to one rank only) stops the run within a coupling step
                  with a checkpoint, exit code 143 and the command to continue; continuing it appends rows.
                  The same signals while LIGGGHTS fills and settles the bed end the job at once (non-zero, a line
                  saying no checkpoint exists yet, the case folder unchanged).
                  A checkpoint that takes longer than mpirun's grace after a signal (odls_base_sigkill_timeout,
                  0 s here) is warned about once; with a grace of 30 s it is not.
"""
import glob
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, copy_case, fail, replace_in_file, run  # noqa: E402

N = 50
GAS_STEP = 2.0e-4


AVERAGE_START = 20 * GAS_STEP


def edit(settings):
    settings["output"].update({"monitor_interval": GAS_STEP, "checkpoint_interval": N * GAS_STEP,
                               "fields_interval": N * GAS_STEP, "parcels_interval": N * GAS_STEP})
    settings["monitors"]["average"] = {"start": AVERAGE_START}
    # the strict criterion: other_ranks' 1e-6 is the strict solves' 1e-8 grown over N steps; the normalized
    # criterion stops at a continuity error of 1e-6 (2026-12-05 measured with it: 1.17e-6 relative, p_z005)
    for equation in ("pressure", "momentum"):
        settings.setdefault("solver", {}).setdefault(equation, {})["criterion"] = "strict"


def read_averages(out):
    rows = [line.split(",") for line in open(os.path.join(out, "averages.csv")) if not line.startswith(("#", "z"))]
    z = np.array([float(r[0]) for r in rows])
    p = np.array([float(r[1]) for r in rows])
    profile = np.array([[float(r[2]), float(r[3])] for r in rows if r[2]])
    header = open(os.path.join(out, "averages.csv")).readline()
    bed = float(header.split("bed height")[1].split()[0])
    return z, p, profile, bed


def check_averages(out, case):
    m = monitors(out)
    z, p, profile, bed = read_averages(out)
    after = m["time"] > AVERAGE_START + 1e-12
    names = [n for n in m.dtype.names if n.startswith("p_z")]
    expected = np.array([m[n][after].mean() for n in names])
    worst = float(np.max(np.abs(expected - p) / np.abs(expected)))
    print(f"[measured] averaged plane pressures against the mean of the monitor rows: {worst:.3g} relative")
    if worst > 1e-9:
        fail(f"averaged pressures {p} differ from the monitors' mean {expected}")
    g = 9.81
    rho = -(np.diff(p)) / (g * np.diff(z))
    if not np.allclose(profile[:, 1], rho, rtol=1e-9) or not np.allclose(profile[:, 0], 0.5 * (z[1:] + z[:-1])):
        fail(f"profile {profile} is not -(dp)/(g dz) of the averaged pressures")
    half = 0.5 * rho.max()
    mid = profile[:, 0]
    k = next(k for k in range(len(rho) - 1) if rho[k] >= half > rho[k + 1])
    expected_bed = mid[k] + (rho[k] - half) / (rho[k] - rho[k + 1]) * (mid[k + 1] - mid[k])
    print(f"[measured] bed height {bed:.6g} m (from the profile: {expected_bed:.6g} m); bulk density profile "
          f"{np.round(rho, 1).tolist()} kg/m3")
    if abs(bed - expected_bed) > 1e-9 * expected_bed:
        fail("bed height does not follow from the averaged profile")
    with h5py.File(sorted(glob.glob(os.path.join(out, "averages_0*.h5")))[-1]) as f, \
            h5py.File(os.path.join(out, "averages_mesh.h5")) as mesh:
        points = mesh["points"][()].reshape(-1, 8, 3)
        volume = np.prod(points.max(axis=1) - points.min(axis=1), axis=1)
        solids = float(np.sum(f["mean_solids_fraction"][()] * volume))
    import yaml
    variables = yaml.safe_load(open(os.path.join(case, "case.yaml")))["liggghts"]["variables"]
    # `radius` is the parcel's: np beads of dp make one sphere of that volume.
    parcel_volume = int(variables["nparcels"]) * np.pi / 6 * (2 * float(variables["radius"])) ** 3
    print(f"[measured] averaged solids volume {solids:.6e} m3, parcels {parcel_volume:.6e} m3")
    if abs(solids - parcel_volume) > 1e-12 * parcel_volume:
        fail("the averaged solids fraction does not hold the parcels' volume")


def monitors(out):
    return np.genfromtxt(os.path.join(out, "monitors.csv"), delimiter=",", names=True)


def last_fields(out):
    files = sorted(glob.glob(os.path.join(out, "fields_0*.h5")))
    with h5py.File(files[-1]) as f:
        return os.path.basename(files[-1]), {k: f[k][()] for k in f}


def relative_difference(a, b):
    scale = max(np.nanmax(np.abs(a)), 1e-300)
    return float(np.nanmax(np.abs(a - b)) / scale) if np.any(np.isfinite(a)) else 0.0


def compare(a_out, b_out, tolerance, what, ignore=()):
    a, b = monitors(a_out), monitors(b_out)
    if len(b) != len(a) or not np.array_equal(a["time"], b["time"]):
        fail(f"{what}: monitors.csv has {len(b)} rows, the uninterrupted run {len(a)} (times differ or repeat)")
    worst = max((relative_difference(a[n], b[n]), n) for n in a.dtype.names if n not in ignore)
    print(f"[measured] {what}: largest relative monitor difference {worst[0]:.3g} ({worst[1]})")
    if worst[0] > tolerance:
        fail(f"{what}: monitor {worst[1]} differs by {worst[0]:.3g} relative (allowed {tolerance})")
    name_a, fa = last_fields(a_out)
    name_b, fb = last_fields(b_out)
    if name_a != name_b:
        fail(f"{what}: last field snapshot {name_b}, uninterrupted run {name_a} (numbering not continued)")
    field_worst = max(relative_difference(fa[k], fb[k]) for k in fa)
    print(f"[measured] {what}: largest relative field difference in {name_a} {field_worst:.3g}")
    if field_worst > tolerance:
        fail(f"{what}: fields differ by {field_worst:.3g} relative (allowed {tolerance})")
    return a, b


def same_ranks(parcelflow, launcher, work):
    case = copy_case(os.path.join(CASES, "fluidized_column"), work, edit)
    a_out, b_out = os.path.join(work, "A"), os.path.join(work, "B")
    run(launcher + [parcelflow, "run", case, "--output", a_out, "--end", str(2 * N * GAS_STEP)])
    run(launcher + [parcelflow, "run", case, "--output", b_out, "--end", str(N * GAS_STEP)])
    checkpoint = os.path.join(b_out, "checkpoints", "step_%09d" % N)
    run(launcher + [parcelflow, "run", case, "--output", b_out, "--end", str(2 * N * GAS_STEP),
                    "--restart", checkpoint])
    a, b = compare(a_out, b_out, 1e-12, "restart on the same ranks")
    check_averages(a_out, case)
    if open(os.path.join(a_out, "averages.csv")).read().split("written")[1] != \
            open(os.path.join(b_out, "averages.csv")).read().split("written")[1]:
        fail("averages.csv after the restart differs from the uninterrupted run's")
    first = N  # row N (0-based) is the first gas step after the restart
    print(f"[measured] pressure iterations of the first step after the restart: {b['pressure_iterations'][first]:.0f},"
          f" uninterrupted {a['pressure_iterations'][first]:.0f}")
    if abs(b["pressure_iterations"][first] - a["pressure_iterations"][first]) > 1:
        fail("the first gas step after the restart needs another number of pressure iterations")
    with h5py.File(sorted(glob.glob(os.path.join(b_out, "parcels_0*.h5")))[-1]) as f:
        if len(np.unique(f["id"][()])) != len(f["id"][()]):
            fail("the parcel snapshot after the restart repeats ids")
    kept = sorted(os.listdir(os.path.join(b_out, "checkpoints")))
    if kept != ["step_%09d" % N, "step_%09d" % (2 * N)]:
        fail(f"checkpoints kept: {kept}")
    return case, a_out, b_out, checkpoint


def other_ranks(parcelflow, one_rank, work, case, a_out, b_out, checkpoint):
    c_out = os.path.join(work, "C")
    shutil.copytree(b_out, c_out)
    # relative folders, as a user types them (LIGGGHTS runs in the case folder; the paths still resolve)
    relative = [os.path.relpath(p, work) for p in (case, c_out, checkpoint.replace(b_out, c_out))]
    run(one_rank + [os.path.abspath(parcelflow), "run", relative[0], "--output", relative[1], "--end",
                    str(2 * N * GAS_STEP), "--restart", relative[2]], cwd=work)
    # The Krylov iteration counts and the residual they leave (the continuity error) depend on the partition
    # by design; they are not compared.
    compare(a_out, c_out, 1e-6, "restart of a 2-rank checkpoint on 1 rank",
            ignore=("pressure_iterations", "pressure_iterations_total", "momentum_iterations", "continuity_error"))


def refusals(parcelflow, launcher, work, case, b_out):
    first, second = (os.path.join(b_out, "checkpoints", "step_%09d" % k) for k in (N, 2 * N))
    import yaml
    other = os.path.join(work, "other_case")
    shutil.copytree(case, other)
    settings = yaml.safe_load(open(os.path.join(other, "case.yaml")))
    settings["coupling"]["drag"] = "Gidaspow"
    yaml.safe_dump(settings, open(os.path.join(other, "case.yaml"), "w"))
    mixed = os.path.join(work, "mixed")
    shutil.copytree(first, mixed)
    shutil.copy(os.path.join(second, "gas.h5"), os.path.join(mixed, "gas.h5"))
    damaged_gas = os.path.join(work, "damaged_gas")  # used to end in an HDF5 exception, exit code 1
    shutil.copytree(first, damaged_gas)
    open(os.path.join(damaged_gas, "gas.h5"), "wb").write(os.urandom(5000))
    edited_time = os.path.join(work, "edited_time")  # used to run on from a loop time of -1
    shutil.copytree(first, edited_time)
    loop = os.path.join(edited_time, "loop.yaml")
    text = open(loop).read()
    open(loop, "w").write(text.replace("  time: ", "  time: -1 #", 1))
    # an output folder without the parcel series it continues: used to stop after LIGGGHTS started, exit code 1
    no_parcels = os.path.join(work, "no_parcels")
    shutil.copytree(b_out, no_parcels, ignore=shutil.ignore_patterns("checkpoints"))
    os.remove(os.path.join(no_parcels, "parcels_000000.h5"))
    for folder, out, restart, expected in [(other, b_out, first, "coupling.drag"), (case, b_out, mixed, "checkpoint_id"),
                                           (case, b_out, damaged_gas, "gas.h5 = unreadable"),
                                           (case, b_out, edited_time, "loop.time = -1"),
                                           (case, no_parcels, first, "parcels_000000.h5 = missing")]:
        done = subprocess.run(launcher + [parcelflow, "run", folder, "--output", out, "--restart", restart],
                              capture_output=True, text=True)
        if done.returncode != 2 or expected not in done.stderr or "checkpoint" not in done.stderr:
            fail(f"restart from {restart} of {folder}: exit {done.returncode}, expected 2 naming {expected}:\n"
                 f"{done.stdout[-1500:]}{done.stderr[-1500:]}")
        message = [line for line in done.stderr.splitlines() if line.startswith("parcelflow:")]
        print(f"[measured] refused: {message[0][:200] if message else '(no parcelflow message)'}")


def signalled_run(parcelflow, launcher, case, out, to_one_rank, ready):
    """Starts a run of `case`, waits until ready() (at most 300 s), sends SIGTERM to mpirun or to one rank;
    (job, stdout, stderr, seconds from the signal to the end)."""
    job = subprocess.Popen(launcher + [parcelflow, "run", case, "--output", out, "--end", "5"],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 300
    while time.time() < deadline and not ready():
        time.sleep(0.2)
    sent = time.time()
    if to_one_rank:
        ranks = subprocess.run(["pgrep", "-f", "-P", str(job.pid), "parcelflow"], capture_output=True,
                               text=True).stdout.split()
        if not ranks:
            fail("no rank process found under mpirun")
        os.kill(int(ranks[-1]), signal.SIGTERM)
    else:
        job.send_signal(signal.SIGTERM)
    stdout, stderr = job.communicate(timeout=300)
    return job, stdout, stderr, time.time() - sent


def stop_with_signal(parcelflow, launcher, work, to_one_rank):
    case = copy_case(os.path.join(CASES, "fluidized_column"), os.path.join(work, "signal"), edit)
    out = os.path.join(work, "signal", "out")
    csv = os.path.join(out, "monitors.csv")
    job, stdout, stderr, _ = signalled_run(parcelflow, launcher, case, out, to_one_rank,
                                           lambda: os.path.exists(csv) and sum(1 for _ in open(csv)) >= 30)
    if job.returncode == 0 or "--restart" not in stderr:
        fail(f"SIGTERM: exit {job.returncode}, expected non-zero and how to continue:\n{stdout[-1500:]}{stderr[-1500:]}")
    checkpoint = stderr.split("--restart")[-1].split()[0]
    rows = len(monitors(out))
    print(f"[measured] SIGTERM ({'one rank' if to_one_rank else 'mpirun'}): exit {job.returncode} after "
          f"{rows} monitor rows, checkpoint {os.path.basename(checkpoint)}")
    stopped_at = int(os.path.basename(checkpoint).split("_")[1])
    if rows != stopped_at:
        fail(f"monitors.csv has {rows} rows at a checkpoint after {stopped_at} gas steps")
    end = (stopped_at + 10) * GAS_STEP
    run(launcher + [parcelflow, "run", case, "--output", out, "--end", repr(end), "--restart", checkpoint])
    m = monitors(out)
    if len(m) != stopped_at + 10 or np.any(np.diff(m["time"]) <= 0):
        fail(f"after continuing: {len(m)} rows, expected {stopped_at + 10} with increasing times")
    for leftover in glob.glob(os.path.join(os.path.dirname(case), "restart_forced*")) + \
            glob.glob(os.path.join(case, "restart_forced*")):
        fail(f"a file was written into the case folder: {leftover}")


def stop_during_start_up(parcelflow, launcher, work, to_one_rank):
    """A signal while LIGGGHTS fills and settles the bed (before the coupled loop) used to end the job by the
    default action: exit code 1 and no word. Now every rank that gets it says so and ends at once."""
    folder = os.path.join(work, "start_up")
    shutil.rmtree(folder, ignore_errors=True)
    def long_settling(case):  # so that the signal lands inside the script on an idle machine too
        replace_in_file(os.path.join(case, "column.in"), [("run             12000\n", "run             400000\n")])
    case = copy_case(os.path.join(CASES, "fluidized_column"), folder, edit, long_settling)
    before = sorted(os.listdir(case))
    out = os.path.join(folder, "out")
    log = os.path.join(out, "log.liggghts")
    job, stdout, stderr, took = signalled_run(parcelflow, launcher, case, out, to_one_rank,
                                              lambda: os.path.exists(log) and "Step" in open(log).read())
    words = "stopped by a signal before the coupled run started"
    if job.returncode == 0 or words not in stderr or "monitors.csv" in os.listdir(out) or took > 30:
        fail(f"SIGTERM during the script: exit {job.returncode} after {took:.1f} s, expected non-zero, '{words}' "
             f"and no monitors.csv:\n{stdout[-1500:]}{stderr[-1500:]}")
    if sorted(os.listdir(case)) != before:
        fail(f"the case folder changed: {sorted(os.listdir(case))} (before: {before})")
    print(f"[measured] SIGTERM during the script ({'one rank' if to_one_rank else 'mpirun'}): exit {job.returncode} "
          f"{took:.1f} s after the signal: " + [l for l in stderr.splitlines() if words in l][0])


def slow_checkpoint_warning(parcelflow, launcher, work):
    case = copy_case(os.path.join(CASES, "fluidized_column"), os.path.join(work, "grace"), edit)
    warning = "a SIGTERM or Ctrl-C to mpirun would lose the checkpoint"
    os.environ["OMPI_MCA_odls_base_sigkill_timeout"] = "30"
    try:
        quick = run(launcher + [parcelflow, "run", case, "--output", os.path.join(work, "grace", "a"),
                                "--end", str(N * GAS_STEP)])
        os.environ["OMPI_MCA_odls_base_sigkill_timeout"] = "0"
        slow = run(launcher + [parcelflow, "run", case, "--output", os.path.join(work, "grace", "b"),
                               "--end", str(2 * N * GAS_STEP)])
    finally:
        del os.environ["OMPI_MCA_odls_base_sigkill_timeout"]
    if warning in quick or slow.count(warning) != 1:
        fail(f"slow-checkpoint warning: {quick.count(warning)} times with a grace of 30 s (expected 0), "
             f"{slow.count(warning)} times with 0 s and two checkpoints (expected 1)")
    print("[measured] " + [l for l in slow.splitlines() if warning in l][0])


def main():
    parcelflow, mpiexec, mode = sys.argv[1], sys.argv[2], sys.argv[3]
    ranks = int(sys.argv[4])
    launcher = [mpiexec] + sys.argv[5:] + ["-np", str(ranks)]
    work = tempfile.mkdtemp(prefix="pf_restart_")
    try:
        if mode == "restart":
            case, a_out, b_out, checkpoint = same_ranks(parcelflow, launcher, work)
            if ranks == 2:
                other_ranks(parcelflow, [mpiexec] + sys.argv[5:] + ["-np", "1"], work, case, a_out, b_out, checkpoint)
            refusals(parcelflow, launcher, work, case, b_out)
        else:
            stop_with_signal(parcelflow, launcher, work, to_one_rank=False)
            stop_during_start_up(parcelflow, launcher, work, to_one_rank=False)
            slow_checkpoint_warning(parcelflow, launcher, work)
            if ranks == 2:
                shutil.rmtree(os.path.join(work, "signal"))
                stop_with_signal(parcelflow, launcher, work, to_one_rank=True)
                stop_during_start_up(parcelflow, launcher, work, to_one_rank=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("PASS")


if __name__ == "__main__":
    main()
