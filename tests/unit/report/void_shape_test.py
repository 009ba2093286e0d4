#!/usr/bin/python3
"""Unit test of cases/report/void_shape.py on synthetic fields with known bubbles
and layers: a 47 x 94 cell bed (the Goldschmidt mesh) of solids fraction 0.6 up to row 30 under a gas-only
freeboard, with voids carved into it."""
import os
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "cases", "report"))
import void_shape  # noqa: E402

NX, NZ, DX = 47, 94, 0.15 / 47


def bed():
    a = np.ones((NZ, NX))
    a[:30, :] = 0.4
    return a


def carve_disc(a, zc, xc, r):
    z, x = np.mgrid[0:NZ, 0:NX]
    a[(z - zc) ** 2 + (x - xc) ** 2 <= r * r] = 0.95


class VoidShape(unittest.TestCase):
    def test_a_bed_without_voids_has_neither_layer_nor_bubble(self):
        self.assertEqual(void_shape.snapshot_measure(bed(), DX), (False, 0, []))

    def test_two_round_bubbles_are_counted_with_their_widths(self):
        a = bed()
        carve_disc(a, 10, 12, 4)  # 9 columns wide
        carve_disc(a, 18, 33, 3)  # 7 columns wide
        layer, count, widths = void_shape.snapshot_measure(a, DX)
        self.assertFalse(layer)
        self.assertEqual(count, 2)
        self.assertEqual(sorted(np.rint(np.array(widths) / DX).astype(int)), [7, 9])

    def test_holdup_splits_the_bed_into_voids_and_emulsion(self):
        a = bed()
        a[5:7, :] = 0.9  # a layer of 2 x 47 cells
        a[20:22, 10:12] = 0.95  # a bubble of 4 cells
        a[25, 30] = 0.9  # a gap of one cell: emulsion
        share, emulsion = void_shape.holdup(a)
        self.assertAlmostEqual(share, (2 * NX + 4) / (30 * NX), places=12)
        self.assertAlmostEqual(emulsion, (0.4 * (30 * NX - 2 * NX - 5) + 0.9) / (30 * NX - 2 * NX - 4), places=12)
        share, emulsion = void_shape.holdup(bed())
        self.assertEqual(share, 0.0)
        self.assertAlmostEqual(emulsion, 0.4, places=12)

    def test_a_layer_across_the_width_is_a_layer_not_a_bubble(self):
        a = bed()
        a[12:14, 1:46] = 0.9  # 45 of 47 columns: more than 80 %
        self.assertEqual(void_shape.snapshot_measure(a, DX), (True, 0, []))

    def test_a_void_across_70_percent_of_the_width_is_a_bubble(self):
        a = bed()
        a[12:14, 0:33] = 0.9  # 33 of 47 columns
        layer, count, widths = void_shape.snapshot_measure(a, DX)
        self.assertEqual((layer, count), (False, 1))
        self.assertAlmostEqual(widths[0], 33 * DX)

    def test_gaps_smaller_than_min_cells_and_the_freeboard_are_not_voids(self):
        a = bed()
        a[5, 5:8] = 0.9  # 3 cells < MIN_CELLS
        a[30:, :] = 1.0  # freeboard: above every column's surface
        self.assertEqual(void_shape.snapshot_measure(a, DX), (False, 0, []))

    def test_a_void_open_to_the_surface_is_outside_the_bed(self):
        a = bed()
        a[25:30, 20:26] = 0.95  # an erupting bubble: nothing dense above it in its columns
        self.assertEqual(void_shape.snapshot_measure(a, DX), (False, 0, []))

    def test_a_plane_with_holes_measures_its_width_in_cells_it_has(self):
        a = bed()
        a[:, :5] = np.nan  # outside a vessel of cut cells: 42 columns of gas cells
        a[:, -5:] = np.nan
        a[12:14, 6:41] = 0.9  # 35 of 37 columns: a layer there (35 > 0.8 x 37), a bubble on the full 47 (< 37.6)
        self.assertEqual(void_shape.snapshot_measure(a, DX), (True, 0, []))
        share, emulsion = void_shape.holdup(a)
        self.assertAlmostEqual(share, 70 / (30 * 37))
        self.assertAlmostEqual(emulsion, 0.4)
        b = bed()
        b[:, :5] = np.nan
        self.assertAlmostEqual(void_shape.lateral_spread(b), 0.0, places=14)  # holes are not gas

    def test_lateral_spread_is_zero_for_flat_bands_and_known_for_a_half_void_row(self):
        a = bed()
        a[12:14, :] = 0.9  # a flat band: each row uniform across the width
        self.assertAlmostEqual(void_shape.lateral_spread(a), 0.0, places=14)
        b = np.ones((NZ, 4))
        b[:2, :] = 0.4
        b[0, :2] = 0.6  # row 0: 0.6 0.6 0.4 0.4, std 0.1; row 1 uniform; the rest freeboard
        self.assertAlmostEqual(void_shape.lateral_spread(b), 0.05)

    def test_depth_average_of_cells_in_any_order(self):
        rng = np.random.default_rng(1)
        nx, ny, nz = 4, 3, 5
        x, y, z = np.meshgrid((np.arange(nx) + 0.5) * 0.01, (np.arange(ny) + 0.5) * 0.005, (np.arange(nz) + 0.5) * 0.02,
                              indexing="ij")
        centres = np.column_stack([x.ravel(), y.ravel(), z.ravel()])
        values = rng.uniform(0.3, 1.0, size=len(centres))
        order = rng.permutation(len(centres))
        a, dx = void_shape.depth_averaged(values[order], centres[order])
        expected = values.reshape(nx, ny, nz).mean(axis=1).T  # [z, x]
        self.assertAlmostEqual(dx, 0.01)
        np.testing.assert_allclose(a, expected, rtol=1e-14)


if __name__ == "__main__":
    unittest.main()
