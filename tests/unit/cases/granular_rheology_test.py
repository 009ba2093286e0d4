#!/usr/bin/python3
"""Unit test of cases/goldschmidt_segregation/granular_rheology.py on synthetic spheres and contacts: the
Love-Weber stress of one contact against its hand value, the same contact across the periodic depth, the
kinetic stress of two spheres moving apart, the shear rate of a linear velocity field and where it is left out,
and the least-squares viscosity; and the script end to end on dumps of a sheared box."""
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np
import yaml

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "cases", "goldschmidt_segregation")
sys.path.insert(0, HERE)
import granular_rheology as gr  # noqa: E402

MESH = {"lengths": [0.06, 0.01, 0.06], "cells": [6, 1, 6]}  # 1 cm cells: boxes of 2 x 2 cells are 2 cm
MASS, RADIUS = 1e-5, 0.001


def sphere(ident, x, v=(0.0, 0.0, 0.0)):
    return [ident, 1, MASS, RADIUS, *x, *v]


def contact(xi, xj, f):
    """A contact row: positions, velocities (0), ids, periodic flag, the force on the first sphere."""
    return [*xi, *xj, 0, 0, 0, 0, 0, 0, 1, 2, 0, *f]


class Stress(unittest.TestCase):
    def setUp(self):
        self.grid = gr.Grid(MESH, True, 2)
        self.volume = 0.02 * 0.02 * 0.01

    def test_one_contact_gives_its_love_weber_stress(self):
        xi, xj, f = (0.011, 0.005, 0.012), (0.0095, 0.005, 0.0105), (0.3, 0.0, 0.2)
        atoms = np.array([sphere(1, xi), sphere(2, xj)])
        _, _, _, _, shear, pressure = gr.box_state(self.grid, atoms, [np.array([contact(xi, xj, f)])])
        r = np.subtract(xi, xj)
        box = self.grid.index(np.array([xj]))[0]
        self.assertAlmostEqual(shear[box], -0.5 * (f[0] * r[2] + f[2] * r[0]) / self.volume, places=9)
        self.assertAlmostEqual(pressure[box], np.dot(f, r) / (3 * self.volume), places=9)
        self.assertEqual(np.count_nonzero(shear), 1)

    def test_a_contact_across_the_periodic_depth_counts_as_its_nearest_image(self):
        xi, xj, f = (0.011, 0.0005, 0.012), (0.0095, 0.0092, 0.0105), (0.3, 0.4, 0.2)
        near = (0.0095, 0.0092 - 0.01, 0.0105)
        atoms = np.array([sphere(1, xi), sphere(2, xj)])
        across = gr.box_state(self.grid, atoms, [np.array([contact(xi, xj, f)])])
        direct = gr.box_state(self.grid, atoms, [np.array([contact(xi, near, f)])])
        np.testing.assert_allclose(across[4], direct[4], rtol=1e-12)
        np.testing.assert_allclose(across[5], direct[5], rtol=1e-12)

    def test_spheres_moving_apart_give_their_kinetic_stress(self):
        atoms = np.array([sphere(1, (0.005, 0.005, 0.005), (0.1, 0, 0.1)),
                          sphere(2, (0.006, 0.005, 0.005), (-0.1, 0, -0.1))])
        phi, d, ux, uz, shear, pressure = gr.box_state(self.grid, atoms, [np.zeros((0, 18))])
        self.assertAlmostEqual(shear[0], -2 * MASS * 0.01 / self.volume, places=12)
        self.assertAlmostEqual(pressure[0], 2 * MASS * 0.02 / (3 * self.volume), places=12)
        self.assertAlmostEqual(phi[0], 2 * 4 / 3 * np.pi * RADIUS ** 3 / self.volume, places=12)
        self.assertEqual((ux[0], uz[0]), (0.0, 0.0))
        self.assertAlmostEqual(d[0], 2 * RADIUS, places=15)

    def test_a_linear_velocity_field_gives_its_shear_rate_where_the_neighbours_are_dense(self):
        nx, nz = self.grid.shape
        i, k = np.meshgrid(np.arange(nx), np.arange(nz), indexing="ij")
        ux = (3.0 * (k + 0.5) * self.grid.h).ravel()      # dU_x/dz = 3
        uz = (2.0 * (i + 0.5) * self.grid.h).ravel()      # dU_z/dx = 2
        phi = np.full(nx * nz, 0.5)
        rate = gr.shear_rates(self.grid, ux, uz, phi)
        inner = ((i > 0) & (i < nx - 1) & (k > 0) & (k < nz - 1)).ravel()
        np.testing.assert_allclose(rate[inner], 5.0, rtol=1e-12)
        self.assertTrue(np.isnan(rate[~inner]).all())
        phi[1 * nz + 2] = 0.2  # a loose neighbour of the box (1, 1)
        self.assertTrue(np.isnan(gr.shear_rates(self.grid, ux, uz, phi)[1 * nz + 1]))

    def test_the_viscosity_is_the_least_squares_slope(self):
        rate = np.array([1.0, -2.0, 3.0])
        self.assertAlmostEqual(gr.viscosity(0.7 * rate, rate), 0.7, places=12)


class Script(unittest.TestCase):
    def test_a_box_sheared_at_a_known_rate_and_stress(self):
        """3 x 3 boxes of spheres at solids fraction 0.5 moving with U_x = 4 z (1/s), one contact per box: the
        middle box (the only one with four neighbours) reads gamma 4, the contact's pressure, and its shear
        stress over 4 as mu_eff."""
        with tempfile.TemporaryDirectory(prefix="pf_granular_rheology_") as folder:
            run, dumps = os.path.join(folder, "run"), os.path.join(folder, "contacts")
            os.makedirs(run)
            os.makedirs(dumps)
            with open(os.path.join(run, "request.yaml"), "w") as f:
                yaml.safe_dump({"case": {"mesh": MESH, "liggghts": {"variables": {"periodic_depth": "1"}}}}, f)
            with open(os.path.join(dumps, "coupled_step.txt"), "w") as f:
                f.write("100 0.001\n")
            # 0.5 solids per 2 cm box: 2 x 2 x 1 cm / (4/3 pi (1 mm)^3) / 2 spheres
            spheres, pairs, ident = [], [], 1
            per_box = int(round(0.5 * 0.02 * 0.02 * 0.01 / (4 / 3 * np.pi * RADIUS ** 3)))
            for bx in range(3):
                for bz in range(3):
                    for n in range(per_box):
                        x = (0.02 * bx + 0.001 + 0.018 * ((n * 7) % per_box) / per_box, 0.005,
                             0.02 * bz + 0.001 + 0.018 * n / per_box)
                        spheres.append(sphere(ident, x, (4.0 * (0.02 * bz + 0.01), 0, 0)))
                        ident += 1
                    mid = (0.02 * bx + 0.01, 0.005, 0.02 * bz + 0.01)
                    xi, xj = (mid[0], mid[1], mid[2] + 0.001), (mid[0], mid[1], mid[2] - 0.001)
                    pairs.append(contact(xi, xj, (-0.5, 0.0, 0.4)))  # r = (0, 0, 2 mm)
            header = "ITEM: TIMESTEP\n{s}\nITEM: NUMBER OF ATOMS\n{n}\nITEM: BOX BOUNDS ff pp ff\n0 0.06\n0 0.01\n" \
                     "0 0.06\nITEM: ATOMS id type mass radius x y z vx vy vz\n"
            for step in (200, 201):
                with open(os.path.join(dumps, f"atm.{step}.txt"), "w") as f:
                    f.write(header.format(s=step, n=len(spheres)))
                    f.writelines(" ".join(map(str, row)) + "\n" for row in spheres)
                with open(os.path.join(dumps, f"con.{step}.txt"), "w") as f:
                    f.write(header.format(s=step, n=len(pairs)).replace("NUMBER OF ATOMS", "NUMBER OF ENTRIES"))
                    f.writelines(" ".join(map(str, row)) + "\n" for row in pairs)
            volume = 0.02 * 0.02 * 0.01
            shear = 0.5 * 0.5 * 0.002 / volume         # -(f_x r_z + f_z r_x)/2 / V with f_x = -0.5, r_z = 0.002
            done = subprocess.run([sys.executable, os.path.join(HERE, "granular_rheology.py"), run, dumps,
                                   "--tmin", "0", "--box", "2", "--steps", "2"], capture_output=True, text=True,
                                  check=True)
            line = next(row for row in done.stdout.splitlines() if row.startswith("[0.45, 0.55)"))
            boxes, rate, pressure, mu = line.split(", ")[2:6]
            self.assertEqual(int(boxes), 1)                  # only the middle box has four neighbours
            self.assertAlmostEqual(float(rate), 4.0, places=2)
            self.assertAlmostEqual(float(pressure), 0.4 * 0.002 / (3 * volume), places=0)
            self.assertAlmostEqual(float(mu), shear / 4.0, places=3)
            empty = subprocess.run([sys.executable, os.path.join(HERE, "granular_rheology.py"), run, dumps,
                                    "--tmin", "5"], capture_output=True, text=True)
            self.assertNotEqual(empty.returncode, 0)
            self.assertIn("no burst between t = 5 and inf s", empty.stderr)


if __name__ == "__main__":
    unittest.main()
