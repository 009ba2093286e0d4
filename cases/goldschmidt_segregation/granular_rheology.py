#!/usr/bin/env python3
"""How the solids resist shear: the granular phase's local stress against its shear rate from the contact dumps.

usage: granular_rheology.py RUN CONTACTS [--tmin 0.3] [--tmax T] [--box 3] [--steps 6]

RUN and CONTACTS as for contact_exchange.py. Boxes of BOX x BOX gas cells in x-z over the bed's whole depth;
per box and burst that starts at a coupled time in [tmin, tmax]:
- the stress of the contacts averaged over the burst's first --steps DEM steps (Love-Weber: minus the sum of
  f (x) r over the contacts whose midpoint lies in the box, over the box volume; f the force on the pair's first
  sphere, r from its second sphere to it, periodic in y by the nearest image) plus the spheres' kinetic stress
  about the box's mean velocity, at the burst's first step; P a third of minus its trace, sigma_xz its shear;
- the solids fraction (sphere volumes whose centre lies in the box), the mass-weighted mean velocity and
  diameter, and the shear rate gamma = dU_x/dz + dU_z/dx by central differences between neighbouring boxes
  (boxes whose four neighbours all hold at least 0.3 solids).
Printed: per solids-fraction bin, the mean |gamma| and P and the effective viscosity mu_eff (least squares of
sigma_xz = mu_eff gamma); per bin of the inertial number I = |gamma| d / sqrt(P / rho_s) (boxes with P of at
least 0.5 Pa), the friction sigma_xz sign(gamma) / P. A dense granular flow's friction is a function of I
(the mu(I) rheology); at one stress a bed of spheres l times wider then shears l times slower.
"""
import argparse
import os

import numpy as np

from contact_exchange import bursts, run_mesh  # the same files, the same bursts

PHI_BINS = ((0.3, 0.45), (0.45, 0.55), (0.55, 0.6), (0.6, 0.7))
I_BINS = ((0.0, 0.01), (0.01, 0.03), (0.03, 0.1), (0.1, 0.3), (0.3, 1.0), (1.0, 10.0))
DENSE = 0.3         # solids fraction a box and its four neighbours need for a shear rate
LEAST_PRESSURE = 0.5  # Pa: boxes below it have no friction to speak of


class Grid:
    """Boxes of box x box cells in x-z over the whole depth of the run's mesh."""

    def __init__(self, mesh, periodic_y, box):
        cells = np.array(mesh["cells"])
        lengths = np.array(mesh["lengths"], dtype=float)
        self.h = lengths[0] / cells[0] * box
        self.depth = lengths[1]
        self.periodic_y = periodic_y
        self.shape = (int(np.ceil(cells[0] / box)), int(np.ceil(cells[2] / box)))
        self.volume = self.h * self.h * self.depth

    def index(self, x):
        """Flat box index of positions x (n, 3)."""
        i = np.clip((x[:, 0] // self.h).astype(int), 0, self.shape[0] - 1)
        k = np.clip((x[:, 2] // self.h).astype(int), 0, self.shape[1] - 1)
        return i * self.shape[1] + k


def box_state(grid, atoms, contact_steps):
    """Per box (flat arrays): solids fraction, mean diameter, mean velocity (x, z), sigma_xz and P.
    atoms: rows id type mass radius x y z vx vy vz; contact_steps: one array of contact rows (pos_i, pos_j, v_i,
    v_j, id_i, id_j, periodic, f on i) per DEM step."""
    n = grid.shape[0] * grid.shape[1]
    mass, radius, x, v = atoms[:, 2], atoms[:, 3], atoms[:, 4:7], atoms[:, 7:10]
    b = grid.index(x)
    m = np.bincount(b, mass, n)
    held = np.maximum(m, 1e-300)
    phi = np.bincount(b, 4 / 3 * np.pi * radius ** 3, n) / grid.volume
    diameter = np.bincount(b, mass * 2 * radius, n) / held
    u = np.stack([np.bincount(b, mass * v[:, c], n) / held for c in range(3)], axis=1)
    w = v - u[b]
    shear = -np.bincount(b, mass * w[:, 0] * w[:, 2], n) / grid.volume
    pressure = np.bincount(b, mass * np.sum(w * w, axis=1), n) / (3 * grid.volume)
    for pairs in contact_steps:
        if pairs.size == 0:
            continue
        r = pairs[:, 0:3] - pairs[:, 3:6]
        if grid.periodic_y:
            r[:, 1] -= grid.depth * np.round(r[:, 1] / grid.depth)
        at = grid.index(pairs[:, 3:6] + 0.5 * r)
        f = pairs[:, 15:18]
        shear += -np.bincount(at, 0.5 * (f[:, 0] * r[:, 2] + f[:, 2] * r[:, 0]), n) / grid.volume / len(contact_steps)
        pressure += np.bincount(at, np.sum(f * r, axis=1), n) / (3 * grid.volume) / len(contact_steps)
    return phi, diameter, u[:, 0], u[:, 2], shear, pressure


def shear_rates(grid, ux, uz, phi):
    """dU_x/dz + dU_z/dx of the boxes whose four neighbours hold at least DENSE solids (with them), else nan."""
    ux, uz, phi = (a.reshape(grid.shape) for a in (ux, uz, phi))
    rate = np.full(grid.shape, np.nan)
    inner = (slice(1, -1), slice(1, -1))
    rate[inner] = (ux[1:-1, 2:] - ux[1:-1, :-2] + uz[2:, 1:-1] - uz[:-2, 1:-1]) / (2 * grid.h)
    dense = phi > DENSE
    ok = np.zeros(grid.shape, bool)
    ok[inner] = dense[inner] & dense[2:, 1:-1] & dense[:-2, 1:-1] & dense[1:-1, 2:] & dense[1:-1, :-2]
    rate[~ok] = np.nan
    return rate.ravel()


def viscosity(stress, rate):
    """Least-squares mu of stress = mu rate."""
    return float(np.sum(stress * rate) / np.sum(rate * rate))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run")
    p.add_argument("contacts")
    p.add_argument("--tmin", type=float, default=0.3, help="first coupled time of a burst [s]")
    p.add_argument("--tmax", type=float, default=float("inf"), help="last coupled time of a burst [s]")
    p.add_argument("--box", type=int, default=3, help="box edge in gas cells")
    p.add_argument("--steps", type=int, default=6, help="DEM steps of a burst the contact stress is averaged over")
    args = p.parse_args()
    if args.box < 1 or args.steps < 1:
        raise SystemExit(f"--box {args.box}, --steps {args.steps}: both must be at least 1")
    grid = Grid(*run_mesh(args.run), args.box)
    samples, used, density = [], 0, None
    for time, steps in bursts(args.contacts, args.tmin):
        if time > args.tmax:
            break
        used += 1
        atoms = np.loadtxt(os.path.join(args.contacts, f"atm.{steps[0]}.txt"), skiprows=9, ndmin=2)
        density = atoms[0, 2] / (4 / 3 * np.pi * atoms[0, 3] ** 3)
        contacts = [np.loadtxt(os.path.join(args.contacts, f"con.{s}.txt"), skiprows=9, ndmin=2)
                    for s in steps[:args.steps]]
        phi, diameter, ux, uz, shear, pressure = box_state(grid, atoms, contacts)
        rate = shear_rates(grid, ux, uz, phi)
        ok = ~np.isnan(rate)
        samples.append(np.stack([phi[ok], rate[ok], shear[ok], pressure[ok], diameter[ok]], axis=1))
    if not samples:
        raise SystemExit(f"{args.contacts}: no burst between t = {args.tmin:g} and {args.tmax:g} s")
    phi, rate, shear, pressure, diameter = np.concatenate(samples).T
    print(f"{args.contacts}: {used} bursts at t = {args.tmin:g}-{args.tmax:g} s, boxes of {args.box} x {args.box} "
          f"cells over the depth, contact stress over {args.steps} DEM steps, {len(phi)} box samples")
    print("solids fraction, boxes, mean |gamma| [1/s], mean P [Pa], mu_eff [Pa s], mean diameter [mm]")
    for lo, hi in PHI_BINS:
        s = (phi >= lo) & (phi < hi)
        if s.any():
            print(f"[{lo}, {hi}), {s.sum()}, {np.abs(rate[s]).mean():.2f}, {pressure[s].mean():.1f}, "
                  f"{viscosity(shear[s], rate[s]):.3f}, {1e3 * diameter[s].mean():.2f}")
    loaded = pressure >= LEAST_PRESSURE
    inertial = np.abs(rate) * diameter / np.sqrt(np.where(loaded, pressure, 1.0) / density)
    friction = shear * np.sign(rate) / np.where(loaded, pressure, 1.0)
    print("inertial number, boxes, friction mean / median, mean solids fraction, mean P [Pa]")
    for lo, hi in I_BINS:
        s = loaded & (inertial >= lo) & (inertial < hi)
        if s.any():
            print(f"[{lo}, {hi}), {s.sum()}, {friction[s].mean():.3f} / {np.median(friction[s]):.3f}, "
                  f"{phi[s].mean():.3f}, {pressure[s].mean():.1f}")


if __name__ == "__main__":
    main()
