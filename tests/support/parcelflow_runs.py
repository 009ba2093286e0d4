"""What the Python test drivers share: running a program (a failure ends the test with its output) and
running a copy of a case folder with edited settings. Drivers import it after putting tests/support on
sys.path (see any driver's imports)."""
import atexit
import os
import re
import shutil
import subprocess
import sys
import tempfile

import yaml

CASES = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "cases"))


def run(command, cwd=None, timeout=None):
    """Runs command; returns its standard output, or ends the test with FAIL and the output's tail."""
    done = subprocess.run(command, cwd=cwd, capture_output=True, text=True, errors="replace", timeout=timeout)
    if done.returncode != 0:
        sys.exit(f"FAIL: {' '.join(command)} exited with {done.returncode}\n"
                 f"{done.stdout[-3000:]}{done.stderr[-3000:]}")
    return done.stdout


def fail(message):
    """Ends the test with FAIL and the message."""
    sys.exit("FAIL: " + message)


def loop_timing(stdout):
    """The coupled loop's wall time [s] from parcelflow's summary line (LIGGGHTS set-up excluded) and the
    last progress line's split of it ('DEM .. % | coupling .. % | gas .. % | output .. %')."""
    wall = float(re.search(r"simulated in ([0-9.]+) s wall", stdout).group(1))
    progress = [line for line in stdout.splitlines() if line.startswith("t = ")][-1]
    return wall, progress.split("parcel-steps/s")[-1].strip()


LIGGGHTS_LOOP = re.compile(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms")


def liggghts_loop(output):
    """The last `run` of a LIGGGHTS log: its loop time [s], DEM steps and atoms (LIGGGHTS' 'Loop time' line)."""
    seconds, steps, atoms = LIGGGHTS_LOOP.findall(output)[-1]
    return float(seconds), int(steps), int(atoms)


def replace_in_file(path, replacements):
    """Replaces each (old, new) text of `replacements` in file `path`; a missing old text ends the test with
    FAIL (the file changed and the test must follow)."""
    text = open(path).read()
    for old, new in replacements:
        if old not in text:
            fail(f"{path} no longer contains {old!r}: update the test")
        text = text.replace(old, new)
    open(path, "w").write(text)


def apply_test_stopping_criterion(settings):
    """With PARCELFLOW_TEST_STOPPING_CRITERION=strict or normalized in the environment, the case's pressure and
    momentum solves stop by that criterion (issue 30: the coupled tests rerun under the strict one to compare
    with normalized, the default); unset, the case is left as it is."""
    criterion = os.environ.get("PARCELFLOW_TEST_STOPPING_CRITERION")
    if criterion is None:
        return
    if criterion not in ("strict", "normalized"):
        fail(f"PARCELFLOW_TEST_STOPPING_CRITERION={criterion}: allowed is strict or normalized")
    solver = settings.setdefault("solver", {})
    for equation in ("pressure", "momentum"):
        solver.setdefault(equation, {})["criterion"] = criterion


def copy_case(source, work, edit, prepare=lambda case: None):
    """Copies case folder `source` into work/case, applies edit(case_yaml_dict) and prepare(case_folder)
    (and the test stopping criterion of the environment, apply_test_stopping_criterion)."""
    case = os.path.join(work, "case")
    shutil.copytree(source, case, ignore=shutil.ignore_patterns("output"))
    path = os.path.join(case, "case.yaml")
    settings = yaml.safe_load(open(path))
    edit(settings)
    apply_test_stopping_criterion(settings)
    yaml.safe_dump(settings, open(path, "w"))
    prepare(case)
    return case


def establish_checkpoint(parcelflow, launch, source, work, end):
    """Runs a copy of case folder `source` coupled to `end` seconds in `work` (no field output, a checkpoint at
    `end`); returns the case copy's folder and the checkpoint's folder."""
    def edit(settings):
        settings.setdefault("output", {}).update({"checkpoint_interval": end, "fields_interval": 0,
                                                  "progress_interval": 1e6})
    case = copy_case(source, work, edit)
    out = os.path.join(work, "out")
    run(launch + [parcelflow, "run", case, "--output", out, "--end", repr(end)], work)
    folder = os.path.join(out, "checkpoints")
    return case, os.path.join(folder, sorted(os.listdir(folder))[-1])


def dem_restart_command(launch, parcelflow, script, settings, checkpoint, log):
    """`parcelflow dem SCRIPT` with the case's script variables and those that make its script read the
    checkpoint's LIGGGHTS restart (as parcelflow sets them when it continues a checkpoint)."""
    variables = dict(settings["liggghts"].get("variables", {}), dem_step=repr(settings["time"]["dem_step"]),
                     restarting="1", restart_file=os.path.join(checkpoint, "dem.restart"))
    command = launch + [parcelflow, "dem", script, "-log", log]
    for name, value in variables.items():
        command += ["-var", name, str(value)]
    return command


def run_case(parcelflow, launcher, source, edit, prepare=lambda case: None):
    """Runs an edited copy of case folder `source` in a new temporary folder; returns the output folder."""
    work = tempfile.mkdtemp(prefix="pf_verify_")
    atexit.register(shutil.rmtree, work, True)  # the test reads the output until it ends
    case = copy_case(source, work, edit, prepare)
    out = os.path.join(work, "output")
    stdout = run(launcher + [parcelflow, "run", case, "--output", out])
    summary = [l for l in stdout.splitlines() if l.startswith("parcelflow: done")]
    print(summary[-1] if summary else "(no summary line)")
    return out


def expect_nothing_left(work, here_before):
    """Fails if the temporary folder `work` still exists or the working folder holds entries that were not in
    `here_before` (its listing before the runs)."""
    if os.path.exists(work):
        fail(f"the temporary folder {work} is still there")
    left = set(os.listdir(".")) - here_before
    if left:
        fail(f"the runs left {sorted(left)} in the working folder {os.getcwd()}")
