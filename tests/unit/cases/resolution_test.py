#!/usr/bin/python3
"""Unit test of cases/psri_fcc_bubbling_bed/resolution.py: the surface measure on a profile whose crossing is
known, and the record that keeps the runs' rows and profiles with the case (written, read back, and used for
the variants that did not finish in the runs' folder)."""
import argparse
import contextlib
import io
import os
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "cases", "psri_fcc_bubbling_bed")
sys.path.insert(0, HERE)
import resolution  # noqa: E402


class Surface(unittest.TestCase):
    def test_the_first_fall_below_half_the_dense_median_above_1_5_m(self):
        mid = np.arange(0.25, 5.0, 0.5)  # 0.25, 0.75, ..., 4.75
        rho = np.where(mid < 3.0, 600.0, 100.0)
        rho[mid == 2.75] = 400.0  # from 400 at 2.75 m to 100 at 3.25 m: half of 600 at 2.75 + 0.5 / 3
        self.assertAlmostEqual(resolution.surface(mid, rho), 2.75 + 0.5 / 3, places=12)

    def test_a_dip_below_1_5_m_is_not_the_surface_and_no_fall_gives_nan(self):
        mid = np.arange(0.25, 5.0, 0.5)
        rho = np.full_like(mid, 600.0)
        rho[mid == 1.25] = 100.0
        self.assertTrue(np.isnan(resolution.surface(mid, rho)))


class Record(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory(prefix="pf_resolution_")
        self.addCleanup(self.folder.cleanup)
        self.saved = resolution.RECORD
        resolution.RECORD = os.path.join(self.folder.name, "record")
        self.addCleanup(setattr, resolution, "RECORD", self.saved)

    def row(self, name, surface):
        return {"variant": name, "averaged_s": 10.0, "surface_above_sparger_m": surface, "loop_wall_s": 3028.0}

    def test_written_rows_read_back_and_a_rerun_replaces_its_variant(self):
        profile = (np.array([0.25, 0.75]), np.array([600.0, 550.5]))
        with contextlib.redirect_stdout(io.StringIO()):
            resolution.write_record([self.row("baseline", 3.17), self.row("filter_2x", 3.0)],
                                    {"baseline": profile, "filter_2x": profile})
            resolution.write_record([self.row("filter_2x", 3.05)], {"filter_2x": (profile[0], profile[1] + 1)})
        table, profiles = resolution.read_record()
        self.assertEqual(list(table), ["baseline", "filter_2x"])
        self.assertEqual(table["baseline"]["surface_above_sparger_m"], 3.17)
        self.assertEqual(table["filter_2x"]["surface_above_sparger_m"], 3.05)
        np.testing.assert_array_equal(profiles["baseline"][1], [600.0, 550.5])
        np.testing.assert_array_equal(profiles["filter_2x"][1], [601.0, 551.5])

    def test_the_summary_draws_recorded_variants_when_no_run_finished(self):
        profile = (np.array([0.25, 0.75, 1.25]), np.array([600.0, 580.0, 560.0]))
        with contextlib.redirect_stdout(io.StringIO()):
            resolution.write_record([self.row("mesh_50mm", 3.08)], {"mesh_50mm": profile})
        runs = os.path.join(self.folder.name, "runs")
        os.makedirs(runs)
        args = argparse.Namespace(runs=runs, end=30.0, record=False)
        with contextlib.redirect_stdout(io.StringIO()) as out:
            resolution.report(args)
        self.assertIn("mesh_50mm", out.getvalue())
        self.assertTrue(os.path.exists(os.path.join(runs, "resolution_profiles.png")))
        with open(os.path.join(runs, "resolution.csv")) as f:
            self.assertIn("3.08", f.read())

    def test_nothing_finished_and_nothing_recorded_is_told(self):
        args = argparse.Namespace(runs=self.folder.name, end=30.0, record=False)
        with self.assertRaises(SystemExit) as stop:
            resolution.report(args)
        self.assertIn("none recorded", str(stop.exception))


if __name__ == "__main__":
    unittest.main()
