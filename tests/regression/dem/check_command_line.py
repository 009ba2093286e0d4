#!/usr/bin/env python3
"""The parcelflow command line: help, version, usage errors (exit code 2), -var passed to LIGGGHTS, and\nparcelflow's LIGGGHTS styles available before and after `clear`."""
import os
import subprocess
import sys
import tempfile

PROGRAM = sys.argv[1]
results = []


def check(name, args, code, must_contain, cwd=None):
    done = subprocess.run([PROGRAM] + args, capture_output=True, text=True, errors="replace",
                          timeout=60, cwd=cwd)
    text = done.stdout + done.stderr
    ok = done.returncode == code and all(s in text for s in must_contain)
    results.append(ok)
    print(f"{'ok  ' if ok else 'FAIL'} {name}: exit {done.returncode} (want {code})")
    if not ok:
        print(text[-2000:])


check("--help", ["--help"], 0, ["usage: parcelflow run CASE", "parcelflow dem SCRIPT"])
check("--version", ["--version"], 0, ["parcelflow 0.1.0"])
check("no arguments", [], 2, ["no command given", "usage:"])
check("unknown command", ["fly"], 2, ["unknown command 'fly'", "allowed: run, dem"])
check("dem without script", ["dem"], 2, ["needs a LIGGGHTS input script"])
check("dem with unknown option", ["dem", "x.in", "-bogus"], 2, ["unknown option '-bogus'"])
check("dem -var without value", ["dem", "x.in", "-var", "a"], 2, ["-var NAME VALUE"])
check("dem missing script", ["dem", "/nonexistent/in.x"], 2, ["cannot read the LIGGGHTS script '/nonexistent/in.x'"])

with tempfile.TemporaryDirectory() as tmp:
    with open(os.path.join(tmp, "in.var"), "w") as f:
        f.write('print "value of answer: ${answer}"\n')
    check("dem -var reaches the script", ["dem", "in.var", "-var", "answer", "42"], 0,
          ["value of answer: 42"], cwd=tmp)
    check("dem script error reaches the user", ["dem", "in.var"], 1, ["Substitution for illegal variable"],
          cwd=tmp)

# parcelflow's styles exist at start-up and again after `clear` (the post_create hook re-registers them).
PARCEL_SCRIPT = """atom_style granular
atom_modify map array
units si
region box block 0 0.01 0 0.01 0 0.01 units box
create_box 1 box
fix p all parcel mode constant_np np 8
fix i all parcel/implicit_drag
print "styles registered: ${round}"
"""
with tempfile.TemporaryDirectory() as tmp:
    with open(os.path.join(tmp, "in.clear"), "w") as f:
        f.write(PARCEL_SCRIPT.replace("${round}", "before clear") + "clear\n" +
                PARCEL_SCRIPT.replace("${round}", "after clear"))
    check("parcel styles before and after clear", ["dem", "in.clear"], 0,
          ["styles registered: before clear", "styles registered: after clear"], cwd=tmp)

# A wrong key in case.yaml stops `parcelflow run` with exit code 2 before LIGGGHTS starts.
with tempfile.TemporaryDirectory() as tmp:
    with open(os.path.join(tmp, "case.yaml"), "w") as f:
        f.write("liggghts: {script: in.bed}\ntime: {end: 1, gas_step: 1.0e-4, dem_step: 1.0e-5}\n"
                "coupling: {drag: Stokes}\nmesh: {lengths: [1, 1, 1], cells: [2, 2, 2]}\n")
    open(os.path.join(tmp, "in.bed"), "w").close()
    check("run with a wrong case key", ["run", tmp, "--output", os.path.join(tmp, "out")], 2,
          ["coupling.drag", "Stokes", "WenYu"])
    started = os.path.exists(os.path.join(tmp, "out", "log.liggghts"))
    results.append(not started)
    print(f"{'FAIL' if started else 'ok  '} LIGGGHTS did not start for the wrong case")

failed = results.count(False)
print(f"{len(results) - failed} passed, {failed} failed")
sys.exit(1 if failed else 0)
