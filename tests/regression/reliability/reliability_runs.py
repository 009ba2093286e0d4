"""What the reliability drivers share: a tiny copy of cases/fluidized_column (300 parcels instead of 1146, so
LIGGGHTS fills and settles it in about a second) and a run that returns its exit code and output instead of
failing. Every driver is called as DRIVER PARCELFLOW MPIEXEC RANKS [MPIEXEC FLAGS...]."""
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, copy_case, fail  # noqa: E402,F401

COLUMN = os.path.join(CASES, "fluidized_column")
GAS_STEP = 2.0e-4
PARCELS = 300


class Runs:
    """Case copies and runs in one temporary folder, removed by close()."""

    def __init__(self, argv):
        self.parcelflow = argv[1]
        self.launcher = [argv[2]] + argv[4:] + ["-np", argv[3]]
        self.work = tempfile.mkdtemp(prefix="pf_reliability_")
        self.count = 0
        # Every launch's environment: Open MPI's session folder (TMPDIR/ompi.HOST.UID/pid.N) inside work, since
        # an mpirun killed with SIGKILL (killed_run, a timeout) cannot remove it; close() does. Other launchers
        # ignore the variable.
        self.env = dict(os.environ, OMPI_MCA_orte_tmpdir_base=self.work)

    def case(self, edit=lambda s: None, script=lambda text: text):
        """A tiny column with edit(settings) applied to case.yaml and script(text) to column.in."""
        self.count += 1
        folder = os.path.join(self.work, f"run{self.count}")
        os.makedirs(folder)

        def settings(s):
            s["liggghts"]["variables"]["nparcels"] = str(PARCELS)
            s["output"]["progress_interval"] = 1000
            edit(s)

        def prepare(case):
            path = os.path.join(case, "column.in")
            text = open(path).read()
            open(path, "w").write(script(text))

        return copy_case(COLUMN, folder, settings, prepare)

    def run(self, case, *args, end=10 * GAS_STEP, output=None, timeout=300, ranks=None):
        """(exit code, stdout + stderr, output folder) of `parcelflow run case` (on `ranks` instead of the
        driver's ranks if given)."""
        output = output or os.path.join(os.path.dirname(case), "output")
        launcher = self.launcher if ranks is None else self.launcher[:-1] + [str(ranks)]
        command = launcher + [self.parcelflow, "run", case, "--output", output] + list(args)
        if end is not None:
            command += ["--end", repr(end)]
        try:
            done = subprocess.run(command, capture_output=True, text=True, errors="replace", timeout=timeout,
                                  env=self.env)
        except subprocess.TimeoutExpired:
            fail(f"{' '.join(command)} did not end within {timeout} s")
        return done.returncode, done.stdout + done.stderr, output

    def close(self):
        shutil.rmtree(self.work, ignore_errors=True)


def falling_bed(text):
    """column.in whose floor is removed before the gas starts, parcels that leave the box being lost."""
    text = text.replace("thermo_modify   lost error", "thermo_modify   lost ignore")
    return text.replace("run             2000\n", "run             2000\nunfix wz0\n")


def expect(what, result, code, *words):
    """Checks a run's exit code (None: any non-zero) and that its output names every word."""
    rc, text, _ = result
    if (code is None and rc == 0) or (code is not None and rc != code):
        fail(f"{what}: exit code {rc}, expected {code if code is not None else 'non-zero'}\n{text[-3000:]}")
    missing = [w for w in words if w not in text]
    if missing:
        fail(f"{what}: the output does not name {missing}\n{text[-3000:]}")
    if "core dumped" in text or "Segmentation fault" in text:
        fail(f"{what}: crashed\n{text[-3000:]}")
    line = next((l for l in text.splitlines() if words and words[0] in l), "")
    print(f"[measured] {what}: exit code {rc}: {line.strip()[:300]}")
    return text


def main(checks):
    """Runs check(runs) for each check, then removes the temporary folder."""
    runs = Runs(sys.argv)
    try:
        for check in checks:
            check(runs)
    finally:
        runs.close()
    print("PASS")
