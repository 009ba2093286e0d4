#!/usr/bin/env python3
"""The dry coarse-graining tables, drawn from the run record (records/runs.csv): per box size, every coarse
variant's quantities against the fine runs' (means over each side's realisations), the difference, what the
variant's scaling claims (validate.py's rule: the tolerance, "not claimed", or "outside the rule" where the geometry
is below the parcels' limits), whether it holds, and each side's spread over its realisations; then the runs'
sizes and wall times.

A record row is one case, variant and quantity: the mean over its realisations and their standard deviation
relative to the mean. The Beverloo-fit rows are computed here from the fine runs' c and k with the grain
diameter d replaced by the parcel diameter D.

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
from validate import (BODY_WIDTH_IN_DIAMETERS, OPENING_WIDTH_IN_DIAMETERS, SIZES,  # noqa: E402
                      at_least, claim, compare)

COARSE = ("np8_linear", "np27_linear", "np8_none", "np27_none")  # the claimed scaling first
COLUMN = (("runout", "run-out (L - L0)/L0"), ("wall_height", "final height at the wall / initial"),
          ("centroid_travel", "centroid travel / L0"))


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def spread(value):
    return "-" if not math.isfinite(value) else f"{value:.2g}"


def table(size, rows, out):
    """The comparison table of one box size: rows[(case, variant, quantity)] -> record row."""
    geometry = SIZES[size]
    dp = geometry["dp"]

    def mean(case, variant, quantity):
        row = rows.get((case, variant, quantity))
        return (number(row["mean"]), number(row["std_percent"])) if row else (math.nan, math.nan)

    def line(case, quantity, fine, fine_std, variant, coarse, coarse_std, claimed, within=True):
        tolerance = claim(variant, claimed, within)
        difference, verdict = compare(fine, coarse, tolerance)
        shown = f"{100 * difference:+.1f} %" if math.isfinite(difference) else "-"
        out.write(f"| {case} | {quantity} | {fine:.4g} | {variant} | {coarse:.4g} | {shown} | {tolerance} | {verdict} "
                  f"| {spread(fine_std)} / {spread(coarse_std)} |\n")

    out.write("| case | quantity | fine | variant | coarse | difference | tolerance | pass | std fine / coarse (%) |\n")
    out.write("|---" * 9 + "|\n")
    c, _ = mean("silo", "fine", "beverloo_c")
    k, _ = mean("silo", "fine", "beverloo_k")
    for variant in COARSE:
        diameter = dp * int(variant[2:].split("_")[0]) ** (1 / 3)
        for case, width in geometry["orifices"].items():
            label = f"discharge rate, slot {1e3 * width:.0f} mm"
            fine, fine_std = mean(case, "fine", "rate")
            coarse, coarse_std = mean(case, variant, "rate")
            line(case, label, fine, fine_std, variant, coarse, coarse_std, False)
            predicted = (c * (width - k * diameter)) ** 1.5 if c > 0 and width > k * diameter else math.nan
            line(case, f"{label} / Beverloo fit of the fine runs at D", predicted, math.nan, variant, coarse,
                 coarse_std, True, at_least(width, OPENING_WIDTH_IN_DIAMETERS, diameter))
        line("silo", "Beverloo c: slope of Q^(2/3) against the slot width", *mean("silo", "fine", "beverloo_c"),
             variant, *mean("silo", variant, "beverloo_c"), True)
        line("silo", "Beverloo k: empty annulus / sphere diameter", *mean("silo", "fine", "beverloo_k"), variant,
             *mean("silo", variant, "beverloo_k"), False)
        within = at_least(geometry["column"]["column_width"], BODY_WIDTH_IN_DIAMETERS, diameter)
        for key, label in COLUMN:
            line("column", label, *mean("column", "fine", key), variant, *mean("column", variant, key), True, within)


def run_times(rows, out):
    """Spheres, realisations and wall time of each case's runs."""
    out.write("\n| case | variant | spheres | realisations | wall time of a run [s] |\n|---|---|---|---|---|\n")
    seen = set()
    for (case, variant, _), row in rows.items():
        if row["wall_s"] and (case, variant) not in seen:
            seen.add((case, variant))
            out.write(f"| {case} | {variant} | {row['spheres']} | {row['realisations']} | {row['wall_s']} |\n")


def draw(records, out):
    by_size = defaultdict(dict)
    for row in records:
        by_size[row["size"]][(row["case"], row["variant"], row["quantity"])] = row
    for size in sorted(by_size):
        rows = by_size[size]
        runs = sorted({r["date"] + " " + r["commit"] for r in rows.values()})
        realisations = sorted({f"{r['variant']} {r['realisations']}" for r in rows.values()})
        out.write(f"\n**{size} size** (runs: {', '.join(runs)}; realisations: {', '.join(realisations)})\n\n")
        table(size, rows, out)
        run_times(rows, out)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("record", nargs="?", default=os.path.join(HERE, "records", "runs.csv"))
    args = p.parse_args()
    if not os.path.exists(args.record):
        sys.exit(f"{args.record}: no such run record")
    draw(list(csv.DictReader(open(args.record))), sys.stdout)


if __name__ == "__main__":
    main()
