#!/usr/bin/python3
"""Plots of a fluidized_column run: the report every bed gets (cases/report/README.md), drawn into the run
folder: the bed pressure drop against the bed weight per area, the parcels' mean height, the solids fraction
on the mid-depth plane and the voids, with their statistics over the second half of the run.
Usage: plot.py [OUTPUT_FOLDER] (default: output next to this file)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "report"))
import report  # noqa: E402

folder = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "output")
report.draw(folder, out=folder, title="fluidized_column: 1 mm glass beads, U = 1.0 m/s",
            labels={"mean_z_type1": "1 mm beads"})
