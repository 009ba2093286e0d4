#!/usr/bin/env python3
"""The fluidized coarse-graining tables, drawn from the run record (records/runs.csv, written by
`validate.py --record`): one table per bed (box size, the beads' restitution, one size or the mixture), the fine
bed's seeds as their mean and range, every coarse variant against that mean, and whether it lies within the
quantity's tolerance.

usage: report.py [RECORD]    (RECORD defaults to records/runs.csv beside this file)
"""
import argparse
import csv
import math
import os
import sys
from collections import defaultdict

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from validate import DIAGNOSTICS, QUANTITIES  # noqa: E402

FINE = ("fine", "mono_fine")


def bed_of(row):
    family = "one size (2 mm)" if row["variant"].startswith("mono_") else "mixture (1.5 + 2.5 mm)"
    return row["size"], float(row["restitution"]), family


def column_of(row):
    settings = f" [{row['settings']}]" if row["settings"] else ""
    return row["variant"] + settings


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def tables(rows):
    """{bed: {column: [rows, one per seed]}}, the fine column first in each bed."""
    beds = defaultdict(lambda: defaultdict(list))
    for row in rows:
        beds[bed_of(row)][column_of(row)].append(row)
    return beds


def summary(runs, name):
    """Mean, lowest and highest of the runs that measured `name`, and how many did."""
    values = [number(r[name]) for r in runs]
    finite = [v for v in values if math.isfinite(v)]
    if not finite:
        return math.nan, math.nan, math.nan, 0
    return sum(finite) / len(finite), min(finite), max(finite), len(finite)


def cell(mean, low, high, seeds):
    if not math.isfinite(mean):
        return "-"
    text = f"{mean:.4g}"
    return text + (f" ({low:.4g}-{high:.4g}, {seeds} seeds)" if seeds > 1 else "")


def draw(rows, out):
    beds = tables(rows)
    for bed in sorted(beds):
        columns = beds[bed]
        fine_name = next((c for c in columns if c in FINE), None)
        size, restitution, family = bed
        out.write(f"\n**{size} box, {family}, e = {restitution:g}**\n\n")
        if fine_name is None:
            out.write("(no fine bed recorded yet)\n")
            continue
        fine = columns[fine_name]
        coarse = [c for c in columns if c != fine_name]
        out.write("| quantity | fine | " + " | ".join(coarse) + " | tolerance |\n")
        out.write("|---" * (len(coarse) + 3) + "|\n")
        for name, (tolerance, unit, _) in QUANTITIES.items():
            mean, low, high, seeds = summary(fine, name)
            cells = [cell(mean, low, high, seeds)]
            for c in coarse:
                value, clow, chigh, cseeds = summary(columns[c], name)
                if not math.isfinite(value) or not math.isfinite(mean) or mean == 0:
                    cells.append(cell(value, clow, chigh, cseeds))
                    continue
                difference = value / mean - 1
                verdict = "" if abs(difference) <= tolerance else " **out**"
                cells.append(f"{cell(value, clow, chigh, cseeds)} ({100 * difference:+.1f} %){verdict}")
            label = f"{name} [{unit}]" if unit else name
            out.write(f"| {label} | " + " | ".join(cells) + f" | {100 * tolerance:.0f} % |\n")
        for name in DIAGNOSTICS:
            cells = [cell(*summary(columns[c], name)) for c in [fine_name] + coarse]
            out.write(f"| {name} (no tolerance) | " + " | ".join(cells) + " | |\n")
        wall = [cell(*summary(columns[c], "wall_s")) for c in [fine_name] + coarse]
        out.write("| wall time [s] | " + " | ".join(wall) + " | |\n")
        runs = [r for c in [fine_name] + coarse for r in columns[c]]
        out.write(f"\nRuns: {', '.join(sorted({r['date'] + ' ' + r['commit'] for r in runs}))}; seeds of the fine "
                  f"bed: {', '.join(r['seed'] for r in fine)}.\n")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("record", nargs="?", default=os.path.join(HERE, "records", "runs.csv"))
    args = p.parse_args()
    if not os.path.exists(args.record):
        sys.exit(f"{args.record}: no such run record (validate.py --record writes it)")
    draw(list(csv.DictReader(open(args.record))), sys.stdout)


if __name__ == "__main__":
    main()
