#!/usr/bin/python3
"""Unit test of cases/report/report.py on tiny synthetic run folders whose numbers are known by hand.

Thin bed: 10 x 2 x 12 cells of 1 cm (y the depth, 2 cm <= a quarter of the 10 cm width: measured on the depth
average). Gas fraction 0.4 in rows 0-5 (solids 0.6: inside the bed, 10 x 6 = 60 cells), 1 above.
- t = 0.2: a void of 2 x 2 cells at 0.9, before the statistics window (from half the run, 0.5 s);
- t = 0.6: one bubble, columns 3-5 x rows 2-3 at 0.9: void share 6/60 = 0.1, width 3 cm;
- t = 0.8: a layer, row 3 across all 10 columns: void share 10/60, no bubble, a layer.
Over the window: void share (0.1 + 1/6)/2 = 0.133333, bubbles per plane 0.5, width 3 cm, layer share 0.5,
emulsion gas fraction 0.4. Monitors at t = 0.1 ... 1.0: weight per area 200 Pa; in the window (t >= 0.5) the
pressure drop alternates 190, 210 (mean 200, std 10: dp/(W/A) 1.000, rms 0.050) and mean_z_type1 0.02,
0.04 m (mean 30 mm, rms 10 mm); mean_z_type2 is NaN throughout (a wall type): not drawn.
The same bed with x and y swapped (thin along x) gives the same measure. A deep bed of cut cells (6 x 6 x 8
cells, only those of a cylinder of radius 2.8 cells written) with a void across columns 1-4 x rows 2-3: on the
slices at 1/4 and 3/4 of the depth (y rows 1 and 4, whose cells span columns 1-4) it is a layer and holds 8 of
the 4 x 5 inside-bed cells; on the mid slice (y row 3, all 6 columns) it is a 4 cm bubble and holds 8 of 30:
void share (0.4 + 8/30 + 0.4)/3 = 0.355556, 1/3 bubble per plane, and no mesoscale motion (cut cells).
"""
import csv
import os
import subprocess
import sys
import tempfile
import unittest

import h5py
import numpy as np

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "cases", "report")
sys.path.insert(0, HERE)
import report  # noqa: E402

H = 0.01
CORNERS = np.array([(i, j, k) for k in (0, 1) for j in (0, 1) for i in (0, 1)], dtype=float)


def write_mesh(path, cells):
    with h5py.File(path, "w") as f:
        f["points"] = ((cells[:, None, :] + CORNERS[None]) * H).reshape(-1, 3)
        f["cells"] = np.arange(8 * len(cells)).reshape(-1, 8)


def write_snapshot(path, time, gas_fraction, cells):
    with h5py.File(path, "w") as f:
        f["time"] = [time]
        f["gas_fraction"] = gas_fraction
        f["gas_velocity"] = np.tile([0.0, 0.0, 1.0], (len(cells), 1))
        f["solids_velocity"] = np.zeros((len(cells), 3))


def write_monitors(folder):
    t = np.round(np.arange(1, 11) * 0.1, 10)
    dp = np.where(t < 0.5, 300.0, np.where(np.arange(10) % 2 == 0, 190.0, 210.0))
    z1 = np.where(np.arange(10) % 2 == 0, 0.02, 0.04)
    with open(os.path.join(folder, "monitors.csv"), "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["time", "bed_pressure_drop", "bed_weight_per_area", "mean_z_type1", "mean_z_type2", "floor_hits"])
        out.writerows(zip(t, dp, np.full(10, 200.0), z1, np.full(10, np.nan), np.zeros(10)))


def thin_bed(folder, swap=False):
    """The thin bed of the docstring (swap: x the depth)."""
    cells = np.array([(i, j, k) for k in range(12) for j in range(2) for i in range(10)])
    write_mesh(os.path.join(folder, "fields_mesh.h5"), cells[:, [1, 0, 2]] if swap else cells)
    x, z = cells[:, 0], cells[:, 2]
    base = np.where(z <= 5, 0.4, 1.0)
    early = np.where((x >= 1) & (x <= 2) & (z >= 1) & (z <= 2), 0.9, base)
    bubble = np.where((x >= 3) & (x <= 5) & (z >= 2) & (z <= 3), 0.9, base)
    layer = np.where(z == 3, 0.9, base)
    for k, (time, a) in enumerate(((0.2, early), (0.6, bubble), (0.8, layer))):
        write_snapshot(os.path.join(folder, f"fields_{k:06d}.h5"), time, a, cells)
    write_monitors(folder)


def cut_cell_bed(folder):
    """The deep bed of cut cells of the docstring."""
    cells = np.array([(i, j, k) for k in range(8) for j in range(6) for i in range(6)
                      if (i - 2.5) ** 2 + (j - 2.5) ** 2 <= 2.8 ** 2])
    write_mesh(os.path.join(folder, "fields_mesh.h5"), cells)
    x, z = cells[:, 0], cells[:, 2]
    a = np.where(z <= 4, 0.4, 1.0)
    a = np.where((x >= 1) & (x <= 4) & (z >= 2) & (z <= 3), 0.9, a)
    write_snapshot(os.path.join(folder, "fields_000000.h5"), 0.7, a, cells)
    write_monitors(folder)


def png_ok(path):
    if not os.path.isfile(path) or os.path.getsize(path) < 1000:
        return False
    with open(path, "rb") as f:
        return f.read(4) == b"\x89PNG"


def text(path):
    with open(path) as f:
        return f.read()


class Report(unittest.TestCase):
    def test_thin_bed_numbers_and_plots(self):
        with tempfile.TemporaryDirectory(prefix="pf_report_") as folder:
            thin_bed(folder)
            r = report.make(folder)
            v = r["voids"]
            self.assertEqual(v["snapshots"], 2)
            self.assertAlmostEqual(v["void_share"], (0.1 + 10 / 60) / 2, places=12)
            self.assertAlmostEqual(v["bubbles_per_plane"], 0.5, places=12)
            self.assertAlmostEqual(v["bubble_width"], 0.03, places=12)
            self.assertAlmostEqual(v["layer_share"], 0.5, places=12)
            self.assertAlmostEqual(v["emulsion_gas_fraction"], 0.4, places=12)
            self.assertEqual(len(r["void_rows"]), 3)  # the early snapshot is drawn, not counted
            self.assertAlmostEqual(r["start"], 0.5)
            summary = text(os.path.join(folder, "report", "report.txt"))
            self.assertIn("dp/(W/A) 1.000, rms 0.050", summary)
            self.assertIn("mean_z_type1 30.00, 10.00", summary)
            self.assertNotIn("mean_z_type2", summary)
            self.assertIn("void share 0.133", summary)
            self.assertIn("solids box-velocity variance horizontal 0.00, vertical 0.00", summary)  # solids at rest
            for name in ("pressure_drop", "class_heights", "solids_fraction", "voids"):
                self.assertTrue(png_ok(os.path.join(folder, "report", name + ".png")), name)
            self.assertFalse(os.path.exists(os.path.join(folder, "report", "averages_profile.png")))

    def test_a_bed_thin_along_x_is_measured_alike(self):
        with tempfile.TemporaryDirectory(prefix="pf_report_") as folder:
            thin_bed(folder, swap=True)
            v = report.make(folder)["voids"]
            self.assertAlmostEqual(v["void_share"], (0.1 + 10 / 60) / 2, places=12)
            self.assertAlmostEqual(v["bubble_width"], 0.03, places=12)
            self.assertAlmostEqual(v["layer_share"], 0.5, places=12)

    def test_cut_cells_deep_bed_on_slices(self):
        with tempfile.TemporaryDirectory(prefix="pf_report_") as folder:
            cut_cell_bed(folder)
            r = report.make(folder, out=os.path.join(folder, "elsewhere"))
            v = r["voids"]
            self.assertFalse(r["mesh"].box)
            self.assertFalse(r["mesh"].thin())
            self.assertAlmostEqual(v["void_share"], (0.4 + 8 / 30 + 0.4) / 3, places=12)
            self.assertAlmostEqual(v["bubbles_per_plane"], 1 / 3, places=12)
            self.assertAlmostEqual(v["bubble_width"], 0.04, places=12)
            self.assertAlmostEqual(v["layer_share"], 1.0)
            self.assertNotIn("mesoscale", text(os.path.join(folder, "elsewhere", "report.txt")))
            self.assertTrue(png_ok(os.path.join(folder, "elsewhere", "solids_fraction.png")))

    def test_time_averages_and_parcels_are_drawn(self):
        with tempfile.TemporaryDirectory(prefix="pf_report_") as folder:
            thin_bed(folder)
            with open(os.path.join(folder, "averages.csv"), "w") as f:
                f.write("# time averages over 0.5 s from t = 0.5 s, written at t = 1 s; bed height 0.055 m\n"
                        "z,mean_pressure,interval_mid_z,dp_over_g_dz\n0,300,0.025,1000\n0.05,50,0.075,50\n0.1,0,,\n")
            cells = np.array([(i, j, k) for k in range(12) for j in range(2) for i in range(10)])
            write_mesh(os.path.join(folder, "averages_mesh.h5"), cells)
            with h5py.File(os.path.join(folder, "averages_000000.h5"), "w") as f:
                f["time"] = [1.0]
                for k in ("mean_solids_fraction", "mean_gas_speed", "mean_solids_speed"):
                    f[k] = np.linspace(0, 0.6, len(cells))
            with h5py.File(os.path.join(folder, "parcels_000000.h5"), "w") as f:
                f["time"] = [1.0]
                f["position"] = [[0.01, 0.01, 0.01], [0.02, 0.01, 0.03], [0.05, 0.01, 0.02]]
                f["velocity"] = np.zeros((3, 3))
                f["dp"], f["np"], f["type"], f["id"] = [1e-3, 1e-3, 2e-3], [1.0, 1.0, 8.0], [1, 1, 2], [1, 2, 3]
            report.make(folder)
            for name in ("averages_profile", "averages_fields", "parcel_profiles"):
                self.assertTrue(png_ok(os.path.join(folder, "report", name + ".png")), name)
            summary = text(os.path.join(folder, "report", "report.txt"))
            self.assertIn("bed height 0.055 m", summary)
            self.assertIn("parcels at t = 1 s: 3 (type 1 2, type 2 1)", summary)

    def test_command_line_and_bad_input(self):
        with tempfile.TemporaryDirectory(prefix="pf_report_") as folder:
            script = os.path.join(HERE, "report.py")
            empty = os.path.join(folder, "empty")
            os.makedirs(empty)
            done = subprocess.run([sys.executable, script, empty], capture_output=True, text=True)
            self.assertEqual(done.returncode, 2)
            self.assertIn("no monitors.csv", done.stderr)
            thin_bed(folder)
            done = subprocess.run([sys.executable, script, folder, "--start", "5"], capture_output=True, text=True)
            self.assertEqual(done.returncode, 2)
            self.assertIn("--start 5: must lie in [0, 1) s", done.stderr)
            out = os.path.join(folder, "out")
            done = subprocess.run([sys.executable, script, folder, "--out", out, "--start", "0.1"],
                                  capture_output=True, text=True, env=dict(os.environ, MPLCONFIGDIR=folder))
            self.assertEqual(done.returncode, 0, done.stderr)
            # from 0.1 s all three snapshots count: void share (4/60 + 0.1 + 10/60) / 3
            self.assertIn(f"void share {(4 / 60 + 0.1 + 10 / 60) / 3:.3f}", done.stdout)
            self.assertTrue(png_ok(os.path.join(out, "voids.png")))


if __name__ == "__main__":
    unittest.main()
