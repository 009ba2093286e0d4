#!/usr/bin/python3
"""The result tables of a case's validation report (its README.md), drawn from the run records kept with the case.

A case folder with results has `records/tables.yaml`: a list of tables, each

    - name: shipped_20s              # the README's block is marked <!-- table shipped_20s --> ... <!-- end table -->
      file: shipped_20s.csv          # a CSV under records/ (or a path relative to the case folder)
      columns:                       # optional: which columns, their headers and formats (default: all, as stored)
        - {key: segregation, header: "segregation", format: "{:.3f}"}
        - {key: [h_small_mm, h_large_mm], header: "small / large [mm]"}   # values joined by " / "
      where: {variant: baseline}     # optional: only the rows with these values
      note: "2 ranks, 2 s windows"   # optional: said after the date and commit
      commit: 85052be                # optional: for rows that carry no `commit` column
      date: 2026-12-06               # optional: for rows that carry no `date` column
      date_column: recorded          # optional: the record's column that holds the date
      show: false                    # optional: a record kept (superseded or detail) but not shown in the README
      plot: [resolution.py, ...]     # optional: a command (run in the case folder, {out} the plot folder) that
                                     # draws the table's plot from the same records

Each row of a record gives the commit and the date it was measured at (columns `commit` and `date`, or the
table's defaults). When every shown row shares them, the table is followed by one line "Measured DATE at commit
C"; otherwise they are columns of the table.

Exit codes: 0 done, 1 a README table differs from its record (--check), 2 a tables.yaml or record that cannot be
drawn (the message names the file and the problem).

usage: validation_tables.py CASE_FOLDER            print every table of tables.yaml as Markdown
       validation_tables.py CASE_FOLDER --check    exit 1 if a marked block of README.md differs from it
       validation_tables.py CASE_FOLDER --write    rewrite the marked blocks of README.md
       validation_tables.py CASE_FOLDER --plots OUT  also run the tables' plot commands into OUT
"""
import argparse
import csv
import difflib
import os
import re
import subprocess
import sys

import yaml

BLOCK = re.compile(r"<!-- table (\S+) -->\n(.*?)<!-- end table -->", re.S)
META = ("commit", "date")


class RecordError(Exception):
    """A tables.yaml or record that cannot be drawn: the message names the file and the problem."""


def load_specs(case):
    path = os.path.join(case, "records", "tables.yaml")
    if not os.path.exists(path):
        raise RecordError(f"{path}: not found (a case with results lists its tables there)")
    specs = yaml.safe_load(open(path)) or []
    names = [s.get("name") for s in specs]
    for spec in specs:
        for key in ("name", "file"):
            if key not in spec:
                raise RecordError(f"{path}: a table without '{key}': {spec}")
    listed = {s.get("file") for s in specs}
    unlisted = sorted(f for f in os.listdir(os.path.dirname(path)) if f.endswith(".csv") and f not in listed)
    if unlisted:
        raise RecordError(f"{path}: records not listed as a table (add them, with show: false if not shown): "
                          f"{unlisted}")
    for spec in specs:
        if spec.get("plot") and not os.access(os.path.join(os.path.dirname(os.path.dirname(path)), spec["plot"][0]),
                                              os.X_OK):
            raise RecordError(f"{path}: table '{spec['name']}': plot command {spec['plot'][0]} is not an "
                              f"executable file of the case folder")
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        raise RecordError(f"{path}: tables named twice: {duplicates}")
    return specs


def read_rows(case, spec):
    path = os.path.join(case, "records", spec["file"])
    if not os.path.exists(path):
        path = os.path.join(case, spec["file"])
    if not os.path.exists(path):
        raise RecordError(f"table '{spec['name']}': record {spec['file']} not found under {case}")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for key, value in (spec.get("where") or {}).items():
        rows = [r for r in rows if r.get(key) == str(value)]
    if not rows:
        raise RecordError(f"table '{spec['name']}': no rows in {path} (where {spec.get('where')})")
    for row in rows:
        if spec.get("date_column"):
            row["date"] = row.pop(spec["date_column"])
        for key in META:
            if not row.get(key):
                if key not in spec:
                    raise RecordError(f"table '{spec['name']}': a row of {path} has no '{key}' and the table "
                                      f"gives no default: {row}")
                row[key] = str(spec[key])
    return rows


def cell(value, fmt):
    if fmt is None or value in ("", None):
        return value or ""
    try:
        return fmt.format(float(value))
    except ValueError:
        return value


def value(row, column):
    keys = column["key"] if isinstance(column["key"], list) else [column["key"]]
    return " / ".join(cell(row[k], column.get("format")) for k in keys)


def render(case, spec):
    """The table as Markdown lines: header, separator, rows, then the line with the date and commit."""
    rows = read_rows(case, spec)
    columns = spec.get("columns") or [{"key": k} for k in rows[0] if k not in META]
    columns = [c if isinstance(c, dict) else {"key": c} for c in columns]
    for c in columns:
        for key in c["key"] if isinstance(c["key"], list) else [c["key"]]:
            if key not in rows[0]:
                raise RecordError(f"table '{spec['name']}': column '{key}' not in its record "
                                  f"(has: {', '.join(rows[0])})")
    shared = {key: {r[key] for r in rows} for key in META}
    uniform = all(len(values) == 1 for values in shared.values())
    if not uniform:
        columns = columns + [{"key": "date"}, {"key": "commit"}]
    lines = ["| " + " | ".join(c.get("header", str(c["key"])) for c in columns) + " |",
             "|" + "---|" * len(columns)]
    for row in rows:
        lines.append("| " + " | ".join(value(row, c) for c in columns) + " |")
    note = f" ({spec['note']})" if spec.get("note") else ""
    if uniform:
        lines.append("")
        lines.append(f"Measured {shared['date'].pop()} at commit {shared['commit'].pop()}{note}; "
                     f"record `{spec['file']}`.")
    else:
        lines.append("")
        lines.append(f"Record `{spec['file']}`{note}.")
    return lines


def blocks(case, specs):
    return {spec["name"]: "\n".join(render(case, spec)) + "\n" for spec in specs if spec.get("show", True)}


def check(case, specs):
    """The README's marked blocks against the records: a list of problems (empty when they agree)."""
    readme = open(os.path.join(case, "README.md")).read()
    drawn = blocks(case, specs)
    for spec in specs:
        if not spec.get("show", True):
            render(case, spec)  # a record kept but not shown must still be readable
    found = dict(BLOCK.findall(readme))
    problems = [f"README.md has a block '{n}' that tables.yaml does not list" for n in found if n not in drawn]
    for name, text in drawn.items():
        if name not in found:
            problems.append(f"README.md has no block <!-- table {name} --> for the table of tables.yaml")
        elif found[name] != text:
            diff = difflib.unified_diff(found[name].splitlines(), text.splitlines(), "README.md", "records",
                                        lineterm="")
            problems.append(f"table '{name}' differs from its record:\n" + "\n".join(diff))
    return problems


def write(case, specs):
    path = os.path.join(case, "README.md")
    drawn = blocks(case, specs)
    text = BLOCK.sub(lambda m: f"<!-- table {m.group(1)} -->\n{drawn.get(m.group(1), m.group(2))}<!-- end table -->",
                     open(path).read())
    open(path, "w").write(text)


def plots(case, specs, out):
    os.makedirs(out, exist_ok=True)
    for spec in specs:
        if spec.get("plot"):
            command = [os.path.join(case, a) if i == 0 else a.replace("{out}", out)
                       for i, a in enumerate(spec["plot"])]
            print(f"{spec['name']}: {' '.join(command)}", flush=True)
            subprocess.check_call(command, cwd=case)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("case")
    mode = p.add_mutually_exclusive_group()
    mode.add_argument("--check", action="store_true")
    mode.add_argument("--write", action="store_true")
    p.add_argument("--plots", metavar="OUT")
    args = p.parse_args()
    case = os.path.abspath(args.case)
    try:
        specs = load_specs(case)
        if args.check:
            problems = check(case, specs)
            for problem in problems:
                print(f"{os.path.join(args.case, 'README.md')}: {problem}", file=sys.stderr)
            if problems:
                sys.exit(1)
            print(f"{args.case}: {len(specs)} tables match their records")
        elif args.write:
            write(case, specs)
        else:
            for name, text in blocks(case, specs).items():
                print(f"<!-- table {name} -->\n{text}<!-- end table -->\n")
        if args.plots:
            plots(case, specs, os.path.abspath(args.plots))
    except RecordError as e:
        print(f"validation_tables.py: {e}", file=sys.stderr)
        sys.exit(2)


if __name__ == "__main__":
    main()
