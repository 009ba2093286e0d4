#!/usr/bin/env python3
"""`parcelflow dem` must behave exactly like Debian's `liggghts` binary on standard scripts.

Runs LIGGGHTS tutorial scripts (from the liggghts-doc package), shortened and without file dumps, once
with the stock binary and once with `parcelflow dem`, on the same number of MPI ranks, and compares every
row of every thermo table exactly (same library, same decomposition: the numbers must be identical).
"""
import argparse
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import run  # noqa: E402

TUTORIALS = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public"
# tutorial, script, {original run line: shortened run line}
CASES = [
    ("heatTransfer_1", "in.heatGran", {"run\t\t20000 upto": "run 3000 upto", "run\t\t50000 upto": "run 5000 upto"}),
    ("packing", "in.packing", {"variable\tgrowts equal 50000": "variable growts equal 2000",
                               "variable\trelaxts equal 20000": "variable relaxts equal 1000"}),
]


def shortened_script(source, replacements):
    lines = []
    for line in open(source):
        stripped = line.rstrip("\n")
        if stripped.startswith("dump"):
            continue  # file output is not what is compared, and it costs time
        lines.append(replacements.pop(stripped, stripped))
    if replacements:
        sys.exit(f"FAIL: {source} no longer contains the lines {list(replacements)}")
    return "\n".join(lines) + "\n"


def thermo_rows(output):
    """Rows of all thermo tables: the numeric lines between a 'Step ...' header and the 'Loop time' line."""
    rows, inside = [], False
    for line in output.splitlines():
        if re.match(r"\s*Step\s", line):
            inside = True
            rows.append(line.split())
        elif line.startswith("Loop time"):
            inside = False
        elif inside and line.split() and line.split()[0].isdigit():
            rows.append(line.split())  # other lines there are per-rank progress notes, in any order
    return rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--parcelflow", required=True)
    parser.add_argument("--liggghts", default="liggghts")
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--mpiexec", nargs=argparse.REMAINDER, required=True, help="mpirun and its flags (last)")
    args = parser.parse_args()
    launcher = args.mpiexec + ["-np", str(args.ranks)]
    failures = 0
    for tutorial, script, replacements in CASES:
        with tempfile.TemporaryDirectory() as tmp:
            text = shortened_script(os.path.join(TUTORIALS, tutorial, script), dict(replacements))
            outputs = {}
            for name, program in (("stock", [args.liggghts, "-in", script]),
                                  ("parcelflow", [args.parcelflow, "dem", script])):
                folder = os.path.join(tmp, name)
                os.makedirs(os.path.join(folder, "post"))
                with open(os.path.join(folder, script), "w") as f:
                    f.write(text)
                outputs[name] = thermo_rows(run(launcher + program, folder, timeout=600))
            stock, ours = outputs["stock"], outputs["parcelflow"]
            same = stock == ours and len(stock) > 2
            print(f"{tutorial}/{script} on {args.ranks} rank(s): {len(stock)} thermo rows from liggghts, "
                  f"{len(ours)} from parcelflow dem, {'identical' if same else 'DIFFERENT'}")
            if not same:
                failures += 1
                for a, b in zip(stock, ours):
                    if a != b:
                        print(f"  first difference: liggghts {a} vs parcelflow {b}")
                        break
    print(f"{len(CASES) - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
