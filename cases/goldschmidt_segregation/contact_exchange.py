#!/usr/bin/env python3
"""The momentum the small class gives each large sphere through contacts, measured, against kinetic theory.

usage: contact_exchange.py RUN CONTACTS [--tmin 2] [--window 24] [--box 3] [--restitution 0.97] [--friction 0.1]

RUN: a run folder of the Goldschmidt script (its request.yaml gives the mesh); CONTACTS: the folder of its
contact dumps (liggghts.variables.contact_period > 0: every contact and every sphere on contact_burst
consecutive DEM steps every contact_period steps, into liggghts.variables.contact_dir, which a relative path
puts in the case folder, where LIGGGHTS runs; goldschmidt.in). For every burst that starts at a coupled time
of at least
--tmin: per large sphere (atom type 2), F the sum of its contact forces from small spheres (type 1) averaged
over the burst's first --window steps (a few contact times, so that collisions in every phase are summed), and
at the burst's first step w = v - U_s, U_s the small class's mass-weighted mean velocity in the box of
--box^3 gas cells around the sphere's cell (periodic in y with liggghts.variables.periodic_depth 1).
Measured: -F.w over the horizontal components (the vertical one also carries a share of the weight).
Kinetic theory, the model of coupling.class_collisions (coupling/drag/class_collision_drag.hpp) taken for
the spheres of the dump (beads, or parcels with their collision diameters): the force of the small class on
one large sphere, c_sl J(|w|, sqrt(T_s)) w / n_l, with Lebowitz's g0, the box's solids fractions and the
small class's velocity variance T_s in the box. Printed per solids-fraction bin of the box: the large spheres
sampled, their contacts with small ones, both powers per sphere and their ratio (measured / kinetic theory).
"""
import argparse
import glob
import os
import re

import numpy as np
import yaml
from scipy.special import erf

PHI_BINS = np.array([0.3, 0.4, 0.45, 0.5, 0.55, 0.58, 0.6, 0.62, 0.66])
# 8-point Gauss-Legendre on [0, 1], as class_collision_drag.cpp
NODES, WEIGHTS = np.polynomial.legendre.leggauss(8)
NODES, WEIGHTS = 0.5 * (NODES + 1), 0.5 * WEIGHTS


def collision_speed(slip, spread):
    """J(|u|, s) of class_collision_drag.hpp, vectorised; slip and spread > 0."""
    slip, spread = np.maximum(slip, 1e-12), np.maximum(spread, 1e-12)
    total = 0.0
    for c, weight in zip(NODES, WEIGHTS):
        mu = slip * c
        z = mu / spread
        moment = (mu * mu + spread * spread) * erf(z / np.sqrt(2)) / slip + \
            2 * c * spread * np.exp(-0.5 * z * z) / np.sqrt(2 * np.pi)
        total = total + weight * c * moment
    return 2 * np.pi * total


class Boxes:
    """Sums over the box of size^3 cells around every cell (zero outside the mesh, periodic in y if asked)."""

    def __init__(self, mesh, size, periodic_y):
        self.cells = np.array(mesh["cells"])
        self.spacing = np.array(mesh["lengths"], dtype=float) / self.cells
        self.reach, self.periodic_y = size // 2, periodic_y
        self.volume = self.sum(np.full(self.cells, np.prod(self.spacing)))

    def index(self, x):
        return np.clip((x // self.spacing).astype(int), 0, self.cells - 1)

    def deposit(self, cells, values):
        grid = np.zeros(self.cells)
        np.add.at(grid, tuple(cells.T), values)
        return self.sum(grid)

    def sum(self, grid):
        out, r, n = np.zeros_like(grid), self.reach, self.cells
        padded = np.pad(grid, [(r, r), (r, r) if not self.periodic_y else (0, 0), (r, r)])
        if self.periodic_y:
            padded = np.concatenate([padded[:, -r:], padded, padded[:, :r]], axis=1) if r else padded
        for dx in range(2 * r + 1):
            for dy in range(2 * r + 1):
                for dz in range(2 * r + 1):
                    out += padded[dx:dx + n[0], dy:dy + n[1], dz:dz + n[2]]
        return out


def run_mesh(run):
    """(mesh, periodic in y) of a Goldschmidt run folder: its request.yaml's mesh and
    liggghts.variables.periodic_depth."""
    case = yaml.safe_load(open(os.path.join(run, "request.yaml")))["case"]
    return case["mesh"], int(case["liggghts"].get("variables", {}).get("periodic_depth", 0)) == 1


def bursts(folder, tmin):
    """[(coupled time of its first step, its steps)] of every burst of consecutive dumped steps (the spheres'
    dumps, atm.STEP.txt) that starts at a coupled time of at least tmin; coupled_step.txt gives the time."""
    coupled_step, dem_step = open(os.path.join(folder, "coupled_step.txt")).read().split()[:2]
    coupled_step, dem_step = int(coupled_step), float(dem_step)
    runs = []
    for step in sorted(int(re.search(r"atm\.(\d+)\.txt$", f).group(1))
                       for f in glob.glob(os.path.join(folder, "atm.*.txt"))):
        if runs and step == runs[-1][-1] + 1:
            runs[-1].append(step)
        else:
            runs.append([step])
    return [((r[0] - coupled_step) * dem_step, r) for r in runs if (r[0] - coupled_step) * dem_step >= tmin]


def check_force_on_first(pairs, name):
    """The dump's force is taken as the one on the pair's first sphere: then it pushes that sphere away from
    the second one, (x_i - x_j).F > 0, in every pair but those that a periodic boundary separates."""
    distance = np.linalg.norm(pairs[:, 0:3] - pairs[:, 3:6], axis=1)
    near = distance < 2 * np.median(distance)  # touching spheres are a diameter apart, images a box length
    away = np.sum((pairs[near, 0:3] - pairs[near, 3:6]) * pairs[near, 15:18], axis=1) > 0
    if near.sum() > 20 and away.mean() < 0.9:
        raise SystemExit(f"{name}: the contact force pushes the first sphere away from the second in only "
                         f"{100 * away.mean():.0f} % of the pairs: not the force on the first sphere")


def burst_sums(folder, steps, boxes, restitution, friction):
    """Per large sphere of one burst (its steps, the spheres from the first): its phi bin, -F.w and the kinetic
    theory's c J |w|^2 (horizontal)."""
    first = steps[0]
    atoms = np.loadtxt(os.path.join(folder, f"atm.{first}.txt"), skiprows=9, ndmin=2)
    ids, kind, mass, radius = atoms[:, 0].astype(int), atoms[:, 1].astype(int), atoms[:, 2], atoms[:, 3]
    x, v = atoms[:, 4:7], atoms[:, 7:10]
    row = np.full(ids.max() + 1, -1)
    row[ids] = np.arange(len(ids))
    force, contacts = np.zeros((len(ids), 3)), np.zeros(len(ids))
    for step in steps:
        pairs = np.loadtxt(os.path.join(folder, f"con.{step}.txt"), skiprows=9, ndmin=2)
        if pairs.size == 0:
            continue
        i, j, f = row[pairs[:, 12].astype(int)], row[pairs[:, 13].astype(int)], pairs[:, 15:18] / len(steps)
        if (i < 0).any() or (j < 0).any():
            raise SystemExit(f"{folder}: a contact at step {step} names a sphere missing at step {first}")
        check_force_on_first(pairs, f"{folder}/con.{step}.txt")
        on_i = (kind[i] == 2) & (kind[j] == 1)  # the force is on the first sphere of the pair
        on_j = (kind[i] == 1) & (kind[j] == 2)
        np.add.at(force, i[on_i], f[on_i])
        np.add.at(force, j[on_j], -f[on_j])
        np.add.at(contacts, i[on_i], 1.0 / len(steps))
        np.add.at(contacts, j[on_j], 1.0 / len(steps))
    volume = 4 / 3 * np.pi * radius ** 3
    density = mass[0] / volume[0]
    cell = boxes.index(x)
    small = kind == 1
    phi = boxes.deposit(cell, volume) / boxes.volume
    phi_small = boxes.deposit(cell[small], volume[small]) / boxes.volume
    phi_large = boxes.deposit(cell[~small], volume[~small]) / boxes.volume
    small_mass = boxes.deposit(cell[small], mass[small])
    held = np.maximum(small_mass, 1e-300)
    mean = np.stack([boxes.deposit(cell[small], mass[small] * v[small, d]) / held for d in range(3)], axis=-1)
    square = boxes.deposit(cell[small], mass[small] * np.sum(v[small] ** 2, axis=1)) / held
    spread = np.maximum(0.0, (square - np.sum(mean ** 2, axis=-1)) / 3)
    large = np.where(~small & (small_mass[tuple(cell.T)] > 0))[0]
    at = tuple(cell[large].T)
    w = v[large] - mean[at]
    d_s, d_l = 2 * radius[small][0], 2 * radius[~small][0]
    gas = 1 - phi[at]
    g0 = 1 / gas + 3 * d_s * d_l / (gas * gas * (d_s + d_l)) * (phi_small[at] / d_s + phi_large[at] / d_l)
    shape = 3 * (1 + restitution) * (1 + np.pi * friction / 4) * (d_s + d_l) ** 2 / \
        (2 * np.pi * density * (d_s ** 3 + d_l ** 3))
    per_sphere = shape * phi_small[at] * density * density * g0 * np.pi / 6 * d_l ** 3  # c_sl / n_l
    beta = per_sphere * collision_speed(np.linalg.norm(w, axis=1), np.sqrt(spread[at]))
    measured = -(force[large, 0] * w[:, 0] + force[large, 1] * w[:, 1])
    return np.digitize(phi[at], PHI_BINS) - 1, measured, beta * (w[:, 0] ** 2 + w[:, 1] ** 2), contacts[large]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run")
    p.add_argument("contacts")
    p.add_argument("--tmin", type=float, default=2.0, help="first coupled time of a burst [s]")
    p.add_argument("--window", type=int, default=24, help="DEM steps of a burst the force is averaged over")
    p.add_argument("--box", type=int, default=3, help="box of BOX^3 gas cells for the small class's mean")
    p.add_argument("--restitution", type=float, default=0.97)
    p.add_argument("--friction", type=float, default=0.1)
    args = p.parse_args()
    mesh, periodic_y = run_mesh(args.run)
    boxes = Boxes(mesh, args.box, periodic_y)
    bins = len(PHI_BINS) - 1
    total = {k: np.zeros(bins) for k in ("spheres", "measured", "theory", "contacts")}
    used = 0
    for _, burst in bursts(args.contacts, args.tmin):
        members = burst[:args.window]
        if len(members) < args.window:
            continue
        used += 1
        where, measured, theory, contacts = burst_sums(args.contacts, members, boxes, args.restitution, args.friction)
        for b in range(bins):
            s = where == b
            for key, values in (("measured", measured), ("theory", theory), ("contacts", contacts)):
                total[key][b] += values[s].sum()
            total["spheres"][b] += s.sum()
    print(f"{args.run}: {used} bursts from t >= {args.tmin:g} s, forces over {args.window} DEM steps, boxes of "
          f"{args.box}^3 cells")
    print("solids fraction, large spheres, contacts with small ones per sphere, -F.w measured / kinetic theory "
          "[W per sphere], ratio")
    for b in range(bins):
        n = total["spheres"][b]
        if n < 50:
            continue
        print(f"[{PHI_BINS[b]:.2f}, {PHI_BINS[b + 1]:.2f}), {int(n)}, {total['contacts'][b] / n:.2f}, "
              f"{total['measured'][b] / n:.3e} / {total['theory'][b] / n:.3e}, "
              f"{total['measured'][b] / total['theory'][b]:.2f}")
    dense = PHI_BINS[:-1] >= 0.45
    if total["theory"][dense].sum() > 0:
        print(f"solids fraction 0.45-0.66: ratio {total['measured'][dense].sum() / total['theory'][dense].sum():.2f}")


if __name__ == "__main__":
    main()
