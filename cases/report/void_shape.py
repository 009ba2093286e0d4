"""The gas voids of a bed on a vertical plane of cells: bubbles or bed-wide gas layers, and their share of the bed.

A plane a[z, x] holds the gas fraction of one row of cells across the depth (a slice) or its average over the
depth (a quasi-2D bed); NaN marks where the plane has no gas cell (outside a vessel of cut cells).
- The bed surface of a column x is the top of its highest cell whose solids fraction (1 - a) exceeds
  SURFACE_SOLIDS; cells below it are inside the bed.
- A void cell is an inside-bed cell with a > VOID_GAS. Voids are the 4-connected groups of void cells with at
  least MIN_CELLS cells (smaller groups are the gaps between single particles at a fine mesh).
- A void is a layer when the columns it covers span more than LAYER_SPAN of the plane's width (its columns
  that hold a gas cell); otherwise it is a bubble, whose width is the number of columns it covers times the
  cell width.
- The void share (holdup) is the share of the inside-bed cells that lie in voids, layers included.
- The lateral spread is the standard deviation of a across the width, averaged over the rows inside the bed
  (row-mean solids fraction above SURFACE_SOLIDS): a bed of flat bands has little, one with bubbles much.
VOID_GAS is 0.7, below the 0.8 of a bubble's core: a kernel that spreads each particle over a few cells
smears a void's edge, and the threshold is one for every bed so that beds are measured alike.
"""
from collections import deque

import numpy as np

VOID_GAS = 0.7
SURFACE_SOLIDS = 0.3
LAYER_SPAN = 0.8
MIN_CELLS = 4
DEPTH_SLICES = (0.25, 0.5, 0.75)  # where a bed as deep as it is wide is sliced (fractions of its depth)


def cell_indices(centres):
    """([i, j, k] cell indices of the cells at centres along x, y, z of a box mesh, the cell width dx along x
    (1 for a single column))."""
    index, spacing = [], []
    for d in range(3):
        values = np.unique(np.round(centres[:, d], 9))
        spacing.append(np.diff(values)[0] if len(values) > 1 else 1.0)
        index.append(np.rint((centres[:, d] - values[0]) / spacing[d]).astype(int))
    return index, spacing[0]


def depth_averaged(gas_fraction, centres):
    """Reshape a field given per cell (gas_fraction[i] at centres[i] = (x, y, z)) to a[z, x], averaged over
    the cells across the depth y; fields stacked along further axes (gas_fraction[i, k]) give a[z, x, k].
    Returns (a, dx)."""
    index, dx = cell_indices(centres)
    nx, nz = index[0].max() + 1, index[2].max() + 1
    total = np.zeros((nz, nx) + np.shape(gas_fraction)[1:])
    count = np.zeros((nz, nx))
    np.add.at(total, (index[2], index[0]), gas_fraction)
    np.add.at(count, (index[2], index[0]), 1)
    if (count == 0).any():
        raise ValueError("the field does not cover every (x, z) column of a box mesh")
    return total / count.reshape(count.shape + (1,) * (total.ndim - 2)), dx


def depth_slices(gas_fraction, centres, fractions):
    """The field on the rows of cells nearest to each of the depths y = fraction x (bed depth) of a 3D bed,
    as [(a[z, x], dx), ...] (void_shape measures a quasi-2D bed's depth average; a bed as deep as it is wide
    is measured on slices instead); fields stacked along further axes (gas_fraction[i, k]) give a[z, x, k]."""
    index, dx = cell_indices(centres)
    nx, ny, nz = (i.max() + 1 for i in index)
    out = []
    for fraction in fractions:
        j = min(ny - 1, int(fraction * ny))
        on = index[1] == j
        a = np.full((nz, nx) + np.shape(gas_fraction)[1:], np.nan)
        a[index[2][on], index[0][on]] = gas_fraction[on]
        if np.isnan(a).any():
            raise ValueError("the field does not cover every (x, z) cell of a box mesh slice")
        out.append((a, dx))
    return out


def inside_bed(a):
    """The cells of a[z, x] inside the bed: in each column, those up to its highest cell with solids fraction
    above SURFACE_SOLIDS."""
    with np.errstate(invalid="ignore"):
        solid = (1.0 - a) > SURFACE_SOLIDS  # NaN (no cell) is neither solid nor void
    inside = np.zeros_like(solid)
    for x in range(a.shape[1]):
        rows = np.nonzero(solid[:, x])[0]
        if len(rows):
            inside[: rows.max() + 1, x] = True
    return inside


def voids(a):
    """The voids of a[z, x] as lists of (z, x) cells (module docstring)."""
    nz, nx = a.shape
    with np.errstate(invalid="ignore"):
        void = inside_bed(a) & (a > VOID_GAS)
    seen = np.zeros_like(void)
    found = []
    for z0, x0 in zip(*np.nonzero(void)):
        if seen[z0, x0]:
            continue
        group, queue = [], deque([(z0, x0)])
        seen[z0, x0] = True
        while queue:
            z, x = queue.popleft()
            group.append((z, x))
            for dz, dx in ((1, 0), (-1, 0), (0, 1), (0, -1)):
                zz, xx = z + dz, x + dx
                if 0 <= zz < nz and 0 <= xx < nx and void[zz, xx] and not seen[zz, xx]:
                    seen[zz, xx] = True
                    queue.append((zz, xx))
        if len(group) >= MIN_CELLS:
            found.append(group)
    return found


def snapshot_measure(a, dx):
    """(has_layer, bubble count, list of bubble widths [m]) of one snapshot a[z, x]."""
    nx = int(np.isfinite(a).any(axis=0).sum())  # the plane's width in columns (inside a vessel)
    has_layer, widths = False, []
    for group in voids(a):
        columns = len({x for _, x in group})
        if columns > LAYER_SPAN * nx:
            has_layer = True
        else:
            widths.append(columns * dx)
    return has_layer, len(widths), widths


def holdup(a):
    """(share of the inside-bed cells of a[z, x] that lie in voids, layers included; mean gas fraction of the other
    inside-bed cells, the emulsion): where a bed's expansion sits, in its voids or in a looser emulsion."""
    inside = inside_bed(a)
    in_voids = np.zeros_like(inside)
    for group in voids(a):
        in_voids[tuple(np.array(group).T)] = True
    emulsion = inside & ~in_voids
    return (float(in_voids.sum() / inside.sum()) if inside.any() else 0.0,
            float(a[emulsion].mean()) if emulsion.any() else float("nan"))


def lateral_spread(a):
    """Standard deviation of a[z, x] across the width, averaged over the rows inside the bed (0 without any)."""
    held = np.isfinite(a).any(axis=1)
    rows = np.zeros(a.shape[0], dtype=bool)
    rows[held] = (1.0 - np.nanmean(a[held], axis=1)) > SURFACE_SOLIDS
    return float(np.nanstd(a[rows], axis=1).mean()) if rows.any() else 0.0
