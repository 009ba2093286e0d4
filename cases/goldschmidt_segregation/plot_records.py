#!/usr/bin/python3
"""The Goldschmidt report's plots from its records (no run needed): the segregation (h_small - h_large) / h_mean
per 2 s window of every current 20 s run in records/coarse_graining_runs.csv, one panel per bed (walled, periodic
depth), and the shipped case's class heights per window (records/shipped_20s_windows.csv).
Usage: plot_records.py OUT_FOLDER (writes goldschmidt_records_segregation.png there)."""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "records")


def rows(name):
    with open(os.path.join(HERE, name), newline="") as f:
        return list(csv.DictReader(f))


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    runs = [r for r in rows("coarse_graining_runs.csv") if r["status"] == "current" and r["segregation_per_2s_window"]]
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    for ax, bed in zip(axes[:2], ("walled", "periodic depth")):
        for r in (r for r in runs if r["bed"] == bed):
            values = [float(v) for v in r["segregation_per_2s_window"].split()]
            mid = [2 * k + 1 for k in range(len(values))]
            ax.plot(mid, values, "o-", ms=3, lw=1, label=f"{r['run']} (seed {r['insert_seed']})")
        ax.set_title(f"{bed}: segregation per 2 s window")
        ax.set_xlabel("time [s]")
        ax.set_ylabel("(h_small - h_large) / h_mean")
        ax.legend(fontsize=6)
    shipped = rows("shipped_20s_windows.csv")
    mid = [float(r["window"].split("-")[0]) + 1 for r in shipped]
    axes[2].plot(mid, [float(r["small [mm]"]) for r in shipped], "o-", label="1.5 mm beads")
    axes[2].plot(mid, [float(r["large [mm]"]) for r in shipped], "o-", label="2.5 mm beads")
    axes[2].set_title(f"the case as shipped ({shipped[0]['date']}, {shipped[0]['commit']})")
    axes[2].set_xlabel("time [s]")
    axes[2].set_ylabel("mean height of the class [mm]")
    axes[2].legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(out, "goldschmidt_records_segregation.png")
    fig.savefig(path, dpi=110)
    print(path)


if __name__ == "__main__":
    main()
