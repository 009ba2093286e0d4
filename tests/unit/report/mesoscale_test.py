#!/usr/bin/python3
"""Unit test of cases/report/mesoscale.py on synthetic fields of a 6 x 2 x 8 box mesh (1 cm
cells, y the depth) whose bed fills rows 0-5 under a gas-only freeboard: halves of the bed moving apart give
their variance about the centre of mass, cell-scale motion averages out in a box, the solids weight the depth
average, slices of a deep bed keep the motion a depth average cancels, the gas is taken superficial and only
inside the bed, and the snapshots are picked by time."""
import os
import subprocess
import sys
import tempfile
import unittest

import h5py
import numpy as np

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "cases", "report")
sys.path.insert(0, HERE)
import mesoscale  # noqa: E402

NX, NY, NZ, H = 6, 2, 8, 0.01
BED_ROWS = 6
CORNERS = np.array([(i, j, k) for k in (0, 1) for j in (0, 1) for i in (0, 1)], dtype=float)
CELLS = np.array([(i, j, k) for k in range(NZ) for j in range(NY) for i in range(NX)])
CENTRES = (CELLS + 0.5) * H


def bed(solids=0.5):
    """Gas fraction per cell: 1 - solids in the bed's rows, 1 in the freeboard."""
    return np.where(CELLS[:, 2] < BED_ROWS, 1.0 - solids, 1.0)


def velocities(solids_x=0.0, solids_z=0.0, gas_x=0.0, gas_z=0.0):
    """Per-cell velocity arrays (n, 3) from per-cell components."""
    n = len(CELLS)
    s, g = np.zeros((n, 3)), np.zeros((n, 3))
    s[:, 0], s[:, 2], g[:, 0], g[:, 2] = solids_x, solids_z, gas_x, gas_z
    return s, g


class Snapshot(unittest.TestCase):
    def measure(self, gas_fraction, solids_velocity, gas_velocity, box=3):
        return mesoscale.snapshot(gas_fraction, gas_velocity, solids_velocity, CENTRES, box)

    def test_halves_moving_apart_give_their_variance_about_the_centre_of_mass(self):
        left = CELLS[:, 0] < 3
        s, g = velocities(solids_x=np.where(left, 0.2, -0.2), solids_z=0.05)
        var_x, var_z, com_x, com_z, gas_x, gas_z = self.measure(bed(), s, g)
        self.assertAlmostEqual(var_x, 0.04, places=12)
        self.assertAlmostEqual(com_x, 0.0, places=12)
        self.assertAlmostEqual(var_z, 0.0, places=12)  # a bed moving as a whole has no mesoscale motion
        self.assertAlmostEqual(com_z, 0.05, places=12)
        self.assertEqual((gas_x, gas_z), (0.0, 0.0))

    def test_cell_scale_motion_averages_out_in_a_box_but_not_in_a_cell(self):
        s, g = velocities(solids_z=np.where(CELLS[:, 0] % 2 == 0, 0.1, -0.1))
        self.assertAlmostEqual(self.measure(bed(), s, g, box=2)[1], 0.0, places=12)
        self.assertAlmostEqual(self.measure(bed(), s, g, box=1)[1], 0.01, places=12)

    def test_the_solids_weight_the_depth_average(self):
        # Left half: 0.2 solids moving at 1 m/s in front, 0.6 at rest behind: box velocity 0.2/0.8 = 0.25. Right
        # half: 0.4 at rest in both. Equal solids per box, so the centre of mass moves at 0.125.
        left, front = CELLS[:, 0] < 3, CELLS[:, 1] == 0
        solids = np.where(left, np.where(front, 0.2, 0.6), 0.4)
        s, g = velocities(solids_x=np.where(left & front, 1.0, 0.0))
        var_x, _, com_x, _, _, _ = self.measure(bed(solids), s, g)
        self.assertAlmostEqual(com_x, 0.125, places=12)
        self.assertAlmostEqual(var_x, 0.125 ** 2, places=12)

    def test_slices_keep_motion_that_the_depth_average_cancels(self):
        # Front and back rows moving apart along x: the depth average sees a bed at rest, each slice (the mesh is
        # 2 cells deep: the slice at 1/4 is the front row, those at 1/2 and 3/4 the back row) its row's motion.
        front = CELLS[:, 1] == 0
        s, g = velocities(solids_x=np.where(front, 0.3, -0.3))
        self.assertAlmostEqual(self.measure(bed(), s, g)[0], 0.0, places=12)
        var_x, _, com_x, _, _, _ = mesoscale.snapshot(bed(), g, s, CENTRES, 3, slices=True)
        self.assertAlmostEqual(var_x, 0.0, places=12)  # each slice moves as a whole: no motion about its mass centre
        self.assertAlmostEqual(com_x, (0.3 - 0.3 - 0.3) / 3, places=12)  # the slices' centre-of-mass velocities
        left = CELLS[:, 0] < 3
        s, g = velocities(solids_x=np.where(front, np.where(left, 0.2, -0.2), 0.0))
        var_x = mesoscale.snapshot(bed(), g, s, CENTRES, 3, slices=True)[0]
        self.assertAlmostEqual(var_x, 0.04 / 3, places=12)  # the front slice's 0.04, the back slices' 0

    def test_the_gas_is_superficial_and_taken_inside_the_bed_only(self):
        # gas fraction 0.5 in the bed: interstitial 2 and 6 m/s are superficial 1 and 3 (mean 2, variance 1); the
        # freeboard's 100 m/s is outside the bed.
        inside, left = CELLS[:, 2] < BED_ROWS, CELLS[:, 0] < 3
        s, g = velocities(gas_z=np.where(inside, np.where(left, 2.0, 6.0), 100.0))
        self.assertAlmostEqual(self.measure(bed(), s, g)[5], 1.0, places=12)


class RunMeasure(unittest.TestCase):
    def write_run(self, folder, times, speeds):
        with h5py.File(os.path.join(folder, "fields_mesh.h5"), "w") as f:
            f["points"] = ((CELLS[:, None, :] + CORNERS[None, :, :]) * H).reshape(-1, 3)
            f["cells"] = np.arange(8 * len(CELLS)).reshape(-1, 8)
        left = CELLS[:, 0] < 3
        for k, (time, speed) in enumerate(zip(times, speeds)):
            s, g = velocities(solids_x=np.where(left, speed, -speed))
            with h5py.File(os.path.join(folder, f"fields_{k:06d}.h5"), "w") as f:
                f["time"] = [time]
                f["gas_fraction"], f["solids_velocity"], f["gas_velocity"] = bed(), s, g

    def test_the_window_picks_its_snapshots_and_an_empty_one_is_told(self):
        with tempfile.TemporaryDirectory(prefix="pf_mesoscale_") as folder:
            self.write_run(folder, [0.5, 1.0, 1.5, 2.0], [1.0, 0.1, 0.3, 1.0])
            m = mesoscale.run_measure(folder, 1.0, 1.5, 3)
            self.assertEqual(m["snapshots"], 2)
            self.assertAlmostEqual(m["solids_var_x"], (0.01 + 0.09) / 2, places=12)
            self.assertIsNone(mesoscale.run_measure(folder, 3.0, 4.0, 3))
            done = subprocess.run([sys.executable, os.path.join(HERE, "mesoscale.py"), folder, "--start", "3"],
                                  capture_output=True, text=True)
            self.assertEqual(done.returncode, 2)
            self.assertIn("no field snapshot between t = 3 and inf s", done.stderr)
            done = subprocess.run([sys.executable, os.path.join(HERE, "mesoscale.py"), folder, "--start", "1",
                                   "--end", "1.5"], capture_output=True, text=True, check=True)
            self.assertIn(" 2 ", done.stdout)
            self.assertIn("500.0", done.stdout)  # (0.01 + 0.09) / 2 m2/s2 in cm2/s2


if __name__ == "__main__":
    unittest.main()
