#!/usr/bin/python3
"""Unit test of cases/goldschmidt_segregation/contact_exchange.py and dispersion.py on synthetic dumps:
kinetic theory's collision speed in its two limits, the box sums against a brute-force sum, one burst (a large
sphere sliding through resting small ones that push it back) with a known power, a dump whose force is not the
one on the pair's first sphere refused; the dispersion coefficients and drift of spheres moved by known
displacements between two bursts, and two bursts of different spheres refused."""
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "cases",
                                "goldschmidt_segregation"))
import contact_exchange  # noqa: E402
import dispersion  # noqa: E402

HEADER_ATOMS = "ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ATOMS\n{n}\nITEM: BOX BOUNDS ff ff ff\n0 0.03\n0 0.03\n" \
               "0 0.03\nITEM: ATOMS id type mass radius x y z vx vy vz\n"
HEADER_PAIRS = "ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ENTRIES\n{n}\nITEM: BOX BOUNDS ff ff ff\n0 0.03\n0 0.03\n" \
               "0 0.03\nITEM: ENTRIES c[1] c[2] c[3] c[4] c[5] c[6] c[7] c[8] c[9] c[10] c[11] c[12] c[13] c[14] " \
               "c[15] c[16] c[17] c[18]\n"
MESH = {"lengths": [0.03, 0.03, 0.03], "cells": [3, 3, 3]}


def write_burst(folder, steps, push):
    """A large sphere (id 1) at the centre moving at 0.1 m/s in x; 30 small ones (ids 2-31) at rest at +x of it,
    each pushing it with push (N, along x) on every step: the force on the pair's first sphere, the large one."""
    small = [(0.0185, 0.006 + 0.0006 * k, 0.015) for k in range(30)]
    for step in steps:
        with open(os.path.join(folder, f"atm.{step}.txt"), "w") as f:
            f.write(HEADER_ATOMS.format(step=step, n=31))
            f.write("1 2 6.5e-05 0.00125 0.015 0.015 0.015 0.1 0 0\n")
            for k, (x, y, z) in enumerate(small):
                f.write(f"{k + 2} 1 1.4e-05 0.00075 {x} {y} {z} 0 0 0\n")
        with open(os.path.join(folder, f"con.{step}.txt"), "w") as f:
            f.write(HEADER_PAIRS.format(step=step, n=30))
            for k, (x, y, z) in enumerate(small):
                f.write(f"0.015 0.015 0.015 {x} {y} {z} 0.1 0 0 0 0 0 1 {k + 2} 0 {push} 0 0\n")


class ContactExchange(unittest.TestCase):
    def test_collision_speed_has_kinetic_theorys_limits(self):
        slip, spread = 0.3, 0.2
        self.assertAlmostEqual(contact_exchange.collision_speed(slip, 1e-9) / (np.pi / 2 * slip), 1.0, places=6)
        self.assertAlmostEqual(contact_exchange.collision_speed(1e-9, spread) /
                               (8 / 3 * np.sqrt(np.pi / 2) * spread), 1.0, places=6)

    def test_box_sums_match_a_brute_force_sum(self):
        rng = np.random.default_rng(3)
        grid = rng.random((5, 4, 6))
        for size in (3, 5):
            for periodic_y in (False, True):
                boxes = contact_exchange.Boxes({"lengths": [1.0, 1.0, 1.0], "cells": [5, 4, 6]}, size, periodic_y)
                r = size // 2
                expected = np.zeros_like(grid)
                for i, j, k in np.ndindex(grid.shape):
                    for a in range(i - r, i + r + 1):
                        for b in range(j - r, j + r + 1):
                            for c in range(k - r, k + r + 1):
                                if 0 <= a < 5 and 0 <= c < 6 and (periodic_y or 0 <= b < 4):
                                    expected[i, j, k] += grid[a, b % 4, c]
                np.testing.assert_allclose(boxes.sum(grid), expected, rtol=1e-12)

    def test_a_pushed_back_large_sphere_gives_the_power_of_its_push(self):
        boxes = contact_exchange.Boxes(MESH, 3, False)
        with tempfile.TemporaryDirectory(prefix="pf_contact_exchange_") as folder:
            steps = [100, 101, 102, 103]
            write_burst(folder, steps, push=-1e-3)
            where, measured, theory, contacts = contact_exchange.burst_sums(folder, steps, boxes, 0.97, 0.1)
        self.assertEqual(len(measured), 1)
        self.assertAlmostEqual(measured[0], 30 * 1e-3 * 0.1, places=12)  # -F.w, F = -0.03 N, w = 0.1 m/s
        self.assertAlmostEqual(contacts[0], 30.0)
        self.assertGreater(theory[0], 0.0)

    def test_a_force_on_the_second_sphere_is_refused(self):
        boxes = contact_exchange.Boxes(MESH, 3, False)
        with tempfile.TemporaryDirectory(prefix="pf_contact_exchange_") as folder:
            write_burst(folder, [100], push=+1e-3)  # pulls the large sphere towards the small ones
            with self.assertRaises(SystemExit) as refused:
                contact_exchange.burst_sums(folder, [100], boxes, 0.97, 0.1)
        self.assertIn("not the force on the first sphere", str(refused.exception))


def write_spheres(folder, step, rows):
    with open(os.path.join(folder, f"atm.{step}.txt"), "w") as f:
        f.write(HEADER_ATOMS.format(step=step, n=len(rows)))
        for row in rows:
            f.write(" ".join(str(x) for x in row) + " 0 0 0\n")


class Dispersion(unittest.TestCase):
    def test_known_displacements_give_their_coefficients_and_drift(self):
        # type 1 moves +-1 mm in z and +-2 mm in x (variances 1e-6 and 4e-6 m^2), type 2 rises 3 mm together;
        # bursts 2400 steps of 8.3333e-5 s apart: 0.2 s
        start = [(k + 1, 1 + (k >= 10), 1e-5, 1e-3, 0.05, 0.0075, 0.04) for k in range(20)]
        moved = [(i, t, m, r, x + (0.002 * (-1) ** i if t == 1 else 0.0), y,
                  z + (0.001 * (-1) ** i if t == 1 else 0.003)) for i, t, m, r, x, y, z in start]
        with tempfile.TemporaryDirectory(prefix="pf_dispersion_") as folder:
            with open(os.path.join(folder, "coupled_step.txt"), "w") as f:
                f.write("1000 8.3333333333e-05\n")
            write_spheres(folder, 10600, start)   # t = 0.8 s
            write_spheres(folder, 10601, start)   # the burst's second step: not a start
            write_spheres(folder, 13000, moved)   # t = 1.0 s
            starts = dispersion.burst_starts(folder, 0.3)
            per_type, pairs, apart = dispersion.dispersion(starts, 1)
        self.assertEqual([round(t, 6) for t, _ in starts], [0.8, 1.0])
        self.assertEqual(pairs, 1)
        self.assertAlmostEqual(apart, 0.2, places=9)
        np.testing.assert_allclose(per_type[1], [1e-6 / 0.4, 4e-6 / 0.4, 0.0], atol=1e-12)
        np.testing.assert_allclose(per_type[2], [0.0, 0.0, 0.003], atol=1e-12)

    def test_bursts_of_different_spheres_are_refused(self):
        with tempfile.TemporaryDirectory(prefix="pf_dispersion_") as folder:
            with open(os.path.join(folder, "coupled_step.txt"), "w") as f:
                f.write("1000 8.3333333333e-05\n")
            sphere = (1e-5, 1e-3, 0.05, 0.0075, 0.04)
            write_spheres(folder, 10600, [(1, 1) + sphere, (2, 2) + sphere])
            write_spheres(folder, 13000, [(1, 1) + sphere])
            with self.assertRaises(SystemExit):
                dispersion.dispersion(dispersion.burst_starts(folder, 0.3), 1)


if __name__ == "__main__":
    unittest.main()
