#!/usr/bin/env python3
"""The tables of the coarse-graining validation reports are the ones their run records give: for the dry and the
fluidized set, the text of README.md between the markers <!-- report.py --> and <!-- /report.py --> must be
exactly what the set's report.py prints from records/runs.csv, so that a row added to a record or a number
edited in the prose without its record fails here. Writes nothing.

usage: reports_match_records.py"""
import difflib
import os
import subprocess
import sys

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
SETS = ("cases/coarse_graining/dry", "cases/coarse_graining/fluidized")
BEGIN, END = "<!-- report.py -->", "<!-- /report.py -->"


def pasted_tables(readme):
    """The README's text between the markers (each exactly once)."""
    text = open(readme).read()
    if text.count(BEGIN) != 1 or text.count(END) != 1:
        sys.exit(f"FAIL: {readme}: expected {BEGIN} and {END} once each, found {text.count(BEGIN)} and "
                 f"{text.count(END)}")
    return text.split(BEGIN)[1].split(END)[0].strip()


def main():
    failed = False
    for folder in SETS:
        report = os.path.join(REPO, folder, "report.py")
        drawn = subprocess.run([sys.executable, report], capture_output=True, text=True,
                               env=dict(os.environ, PYTHONDONTWRITEBYTECODE="1"))  # no __pycache__ in the cases
        if drawn.returncode != 0:
            sys.exit(f"FAIL: {report} exited with {drawn.returncode}:\n{drawn.stderr}")
        printed = drawn.stdout.strip()
        if "| quantity |" not in printed:
            sys.exit(f"FAIL: {report} printed no table:\n{printed}")
        pasted = pasted_tables(os.path.join(REPO, folder, "README.md"))
        if pasted != printed:
            failed = True
            diff = difflib.unified_diff(pasted.splitlines(), printed.splitlines(), "README.md", "report.py",
                                        lineterm="")
            print(f"FAIL: {folder}/README.md's tables differ from its report.py's output:\n" + "\n".join(diff))
        else:
            print(f"ok: {folder}: README.md's tables are report.py's ({len(printed.splitlines())} lines)")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
