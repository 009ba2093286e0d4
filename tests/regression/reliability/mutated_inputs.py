"""Systematically mutated case.yaml: no input may crash, hang or run on silently. Every leaf of the tiny
column's case.yaml (mappings walked recursively; a list is one leaf, and its first element another) is
removed, or replaced by "x", -1, 0, 1e300 or the mapping {a: 1}, and a list also by one that is one element
short; each mutated case runs 10 gas steps (timeout 120 s). Allowed outcomes: exit code 0 (a valid value or
an optional key), exit code 2 whose output names the mutated key (its last path component), or exit code 3
from the blow-up guard ("diverged"). Everything else fails: a timeout (hang), a crash (a signal, exit code
134/136/139, "Segmentation fault", "terminate called", "core dumped", "Aborted"), exit code 1 or any other
code, and exit code 2 that does not name the key. All mutations run; the failures are listed at the end.
A bad liggghts.variables value stops in LIGGGHTS' own check of the script's command; parcelflow then adds a
line naming the script and the variables and exits with 2 (coupling/dem/dem_engine.cpp). Found with this
driver and fixed: those 13 ended with LIGGGHTS' exit code 1, monitor heights outside the mesh were refused
only after the script's filling and settling, and mesh.lengths 1e300 ran until the blow-up guard.

The product is 234 runs. Most stop with exit code 2 within a second; Open MPI's mpirun would then wait
odls_base_sigkill_timeout (1 s) and more before it ends the job, so the runs set it to 0 (the ranks have ended
already; other launchers ignore the variable), which brings the driver from about 10 to about 3 minutes.
Runs that pass the validation cost LIGGGHTS' filling and settling (about 1 s)."""
import copy
import os
import re
import signal
import subprocess
import time

import yaml

from reliability_runs import COLUMN, GAS_STEP, fail, main

TIMEOUT = 120
END = 10 * GAS_STEP
REMOVE = object()
SCALAR_MUTATIONS = [('"x"', "x"), ("-1", -1), ("0", 0), ("1e300", 1e300), ("{a: 1}", {"a": 1})]
CRASH_WORDS = ("Segmentation fault", "terminate called", "core dumped", "Aborted")
CRASH_CODES = (134, 136, 139)


def leaves(node, path=()):
    """(path, value) of every leaf of a mapping; a list is one leaf."""
    for key, value in node.items():
        if isinstance(value, dict):
            yield from leaves(value, path + (key,))
        else:
            yield path + (key,), value


def label(path):
    return "".join(f"[{p}]" if isinstance(p, int) else ("." if i else "") + p for i, p in enumerate(path))


def edit_for(path, value):
    def edit(settings):
        parent = settings
        for p in path[:-1]:
            parent = parent[p]
        if value is REMOVE:
            del parent[path[-1]]
        else:
            parent[path[-1]] = copy.deepcopy(value)
    return edit


def planned(settings):
    """[(path, mutation label, new value)] for every leaf, in run order."""
    plan = []
    for path, value in leaves(settings):
        plan.append((path, "removed", REMOVE))
        plan += [(path, name, new) for name, new in SCALAR_MUTATIONS]
        if isinstance(value, list):
            plan.append((path, "one element short", value[:-1]))
            plan += [(path + (0,), name, new) for name, new in SCALAR_MUTATIONS]
    return plan


def tail(text, lines=8):
    """The last lines of parcelflow's own output (mpirun's framed notices left out)."""
    kept, framed = [], False
    for line in text.splitlines():
        if re.fullmatch(r"-{20,}", line.strip()):
            framed = not framed
        elif not framed and line.strip():
            kept.append(line.rstrip())
    return kept[-lines:]


def bounded_run(runs, case):
    """(exit code or None after TIMEOUT s, output) of `parcelflow run case --end END`: Runs.run's command, but
    without Open MPI's 1 s grace after a rank's non-zero exit (see above), and a timeout is no end of the test:
    it stops mpirun with SIGTERM (mpirun passes it on to the ranks), then its process group with SIGKILL, so
    that a hung run leaves no rank behind."""
    output = os.path.join(os.path.dirname(case), "output")
    command = runs.launcher + [runs.parcelflow, "run", case, "--output", output, "--end", repr(END)]
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                               errors="replace", start_new_session=True,
                               env=dict(runs.env, OMPI_MCA_odls_base_sigkill_timeout="0"))
    try:
        text, _ = process.communicate(timeout=TIMEOUT)
        return process.returncode, text
    except subprocess.TimeoutExpired:
        process.send_signal(signal.SIGTERM)
        try:
            text, _ = process.communicate(timeout=15)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            text, _ = process.communicate()
        return None, text


def outcome(rc, text, key):
    """'exit 0' / 'exit 2' / 'exit 3' for an allowed outcome, else the reason it fails."""
    crash = [w for w in CRASH_WORDS if w in text]
    if rc is None:
        return f"hang: no end within {TIMEOUT} s"
    if rc < 0 or rc in CRASH_CODES or crash:
        return f"crash: exit code {rc}" + (f", output says {crash}" if crash else "")
    if rc == 2:
        if re.search(rf"\b{re.escape(key)}\b", text):
            return "exit 2"
        return f"exit code 2 without naming '{key}'"
    if rc == 3:
        return "exit 3" if "diverged" in text else "exit code 3 without 'diverged'"
    if rc == 0:
        return "exit 0"
    return f"exit code {rc}"


def mutated_case_yaml(runs):
    plan = planned(yaml.safe_load(open(os.path.join(COLUMN, "case.yaml"))))
    start = time.time()
    counts, failures, exit0 = {"exit 0": 0, "exit 2": 0, "exit 3": 0}, [], []
    for path, name, new in plan:
        key = next(p for p in reversed(path) if isinstance(p, str))
        what = f"{label(path)} {name}" if new is REMOVE else f"{label(path)} = {name}"
        began = time.time()
        rc, text = bounded_run(runs, runs.case(edit_for(path, new)))
        result = outcome(rc, text, key)
        print(f"{what}: {result} ({time.time() - began:.1f} s)", flush=True)
        if result in counts:
            counts[result] += 1
            if result == "exit 0":
                exit0.append(what)
        else:
            failures.append((what, result, tail(text)))
    print(f"[measured] {len(plan)} mutations of case.yaml in {time.time() - start:.0f} s")
    print(f"[measured] exit 0: {counts['exit 0']}: {', '.join(exit0)}")
    print(f"[measured] exit 2 naming the key: {counts['exit 2']}")
    print(f"[measured] exit 3 (blow-up guard): {counts['exit 3']}")
    print(f"[measured] failures: {len(failures)}")
    for what, result, lines in failures:
        print(f"FAILED {what}: {result}: {lines[-1] if lines else '(no output)'}")
        for line in lines:
            print(f"    | {line[:300]}")
    if failures:
        fail(f"{len(failures)} of {len(plan)} mutated inputs crashed, hung, ended with exit code 1 or another "
             f"unexpected one, or did not name the key: " + "; ".join(f"{w}: {r}" for w, r, _ in failures))


if __name__ == "__main__":
    main([mutated_case_yaml])
