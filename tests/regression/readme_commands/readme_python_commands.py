#!/usr/bin/python3
"""Every README command that runs a Python script works as written also where the python3 first on PATH
lacks numpy, h5py and matplotlib (pyenv, conda): a stand-in python3 without Debian's packages
(/usr/bin/python3 -S) goes first on PATH and each such command runs from the repository root. A plot
script gets a temporary run folder (synthetic monitors.csv and fields) instead of the one the README
names and must write PNGs there; other scripts run with --help. A command starting with `python3` fails:
the scripts' shebang (#!/usr/bin/python3) is what finds Debian's python3-h5py and python3-matplotlib.
usage: readme_python_commands.py REPO"""
import csv
import glob
import os
import shlex
import subprocess
import sys
import tempfile

import h5py
import numpy as np


def readmes(repo):
    for root, dirs, files in os.walk(repo):
        dirs[:] = [d for d in dirs if not d.startswith((".", "build", "runs"))]
        if "README.md" in files:
            yield os.path.join(root, "README.md")


def shell_lines(readme):
    """The lines of the README's bash/sh code blocks."""
    shell = None
    for line in open(readme):
        if line.startswith("```"):
            shell = None if shell is not None else line[3:].strip() in ("bash", "sh", "shell")
        elif shell:
            yield line


def fake_run(folder):
    """monitors.csv with the columns the plot scripts read, and two snapshots of gas_fraction on 4x3x5 cells."""
    t = np.linspace(0.0, 2.0, 21)
    with open(os.path.join(folder, "monitors.csv"), "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["time", "mean_z_type1", "mean_z_type2", "bed_pressure_drop", "bed_weight_per_area"])
        out.writerows(zip(t, 0.05 + 0.01 * t, 0.04 - 0.005 * t, 290 + np.sin(t), np.full_like(t, 294.0)))
    lo = np.stack(np.meshgrid(*(0.01 * np.arange(n) for n in (4, 3, 5)), indexing="ij"), -1).reshape(-1, 3)
    corners = np.array([[i, j, k] for k in (0, 1) for j in (0, 1) for i in (0, 1)]) * 0.01
    with h5py.File(os.path.join(folder, "fields_mesh.h5"), "w") as f:
        f["points"] = (lo[:, None, :] + corners[None]).reshape(-1, 3)
    for i in range(2):
        with h5py.File(os.path.join(folder, f"fields_{i:06d}.h5"), "w") as f:
            f["time"] = [0.1 * (i + 1)]
            f["gas_fraction"] = 0.4 + 0.01 * np.arange(len(lo)) / (i + 1)


repo = os.path.abspath(sys.argv[1])
failures, ran = [], 0
with tempfile.TemporaryDirectory(prefix="readme_python_") as tmp:
    bin_dir, run_dir = os.path.join(tmp, "bin"), os.path.join(tmp, "run")
    os.makedirs(bin_dir)
    os.makedirs(run_dir)
    with open(os.path.join(bin_dir, "python3"), "w") as f:
        f.write('#!/bin/sh\nexec /usr/bin/python3 -S "$@"\n')
    os.chmod(os.path.join(bin_dir, "python3"), 0o755)
    env = dict(os.environ, PATH=bin_dir + os.pathsep + os.environ["PATH"], MPLCONFIGDIR=tmp)
    probe = subprocess.run(["python3", "-c", "import numpy"], env=env, capture_output=True)
    assert probe.returncode != 0, "the stand-in python3 still finds numpy"
    fake_run(run_dir)
    for readme in sorted(readmes(repo)):
        for line in shell_lines(readme):
            words = shlex.split(line, comments=True)
            if not any(w.endswith(".py") for w in words):
                continue
            where = f"{os.path.relpath(readme, repo)}: {line.strip()}"
            if words[0].startswith("python"):
                failures.append(f"{where}: starts with {words[0]}; show the script itself (its shebang)")
                continue
            plot = os.path.basename(words[0]) == "plot.py"
            for png in glob.glob(os.path.join(run_dir, "*.png")):
                os.remove(png)
            try:
                result = subprocess.run([words[0], run_dir] if plot else [words[0], "--help"], cwd=repo, env=env,
                                        capture_output=True, text=True)
            except OSError as e:  # not executable, not found
                failures.append(f"{where}: {e}")
                continue
            ran += 1
            if result.returncode != 0:
                failures.append(f"{where}: exit {result.returncode}\n{result.stderr.strip()[-800:]}")
            elif plot and not glob.glob(os.path.join(run_dir, "*.png")):
                failures.append(f"{where}: wrote no PNG")
            else:
                print(f"OK with a python3 lacking numpy first on PATH: {where}")
print("\n".join(failures) if failures else f"readme_python_commands: {ran} commands OK")
sys.exit(1 if failures or ran == 0 else 0)
