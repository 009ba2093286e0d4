#!/usr/bin/python3
"""What coarse graining keeps (issue 14): the Goldschmidt bed fine (one bead per parcel, the case as shipped)
and coarse-grained into fewer, larger parcels of the same beds, run for the same coupled time, side by side:
the segregation (h_small - h_large)/h_mean, the rms of each class's mean height about its mean and
dp/(W/A) over the same window, the run times, and what each bed is made of (parcels, np, dp, solid mass).

Variants (atom types 1 and 2 are the small and the large beads in all of them):
  fine         one bead per parcel: the case as shipped
  np2_linear   2 beads per parcel (l = 2^(1/3) = 1.26): parcels of 1.89 and 3.15 mm
  np3.375_linear  3.375 beads per parcel (l = 1.5): parcels of 2.25 and 3.75 mm, between the beads and np 8
  np8_linear   8 beads per parcel (fix parcel mode constant_np np 8 scaling linear): parcels of 3 and 5 mm,
               1/8 of the parcels; the beads' contact values scaled by l = 2
  np27_linear  27 beads per parcel: parcels of 4.5 and 7.5 mm, l = 3 (for wider beds: cases/coarse_graining/
               fluidized; the 15 mm deep bed holds two 7.5 mm parcels across)
  d5mm_none    5 mm parcels for both classes (mode constant_diameter ... dp_by_type, np 37.04 and 8), parcel
               contact values (scaling none): the beads' spring and restitution with the parcels' masses
  d5mm_linear  the same parcels with the beads' contact values scaled per type pair (scaling linear)
  d2.5mm_linear  2.5 mm parcels of both classes, the largest constant diameter with 6 parcels across the bed's
               15 mm depth (parcel_size_report.h): the small beads np 4.63, the large beads single; scaling linear
  np8_linear_dissipation  np8_linear with the parcel-parcel restitution lowered to e' = sqrt(1 - l (1 - e^2))
               (0.97 -> 0.939 at l = 2): parcels collide 1/l as often per unit mass, so this keeps the
               collisional dissipation per unit mass (kinetic theory; coarse-graining.md); parcel-wall
               contacts keep e (their dissipation per wall area does not depend on the parcel size)
  np8_linear_dissipation_friction  np8_linear_dissipation with the parcel-parcel friction l mu (0.10 -> 0.20):
               the sliding losses of a collision grow about as mu, so this keeps the frictional share of the
               dissipation per unit mass as well (without friction np 8 stops bubbling: README.md); the
               walls keep their friction. It overrides a --set of liggghts.variables.bead_friction
  np8_linear_dissipation_l2  np8_linear with 1 - e'^2 = l^2 (1 - e^2) (0.97 -> 0.874): the collisional pressure
               at one shear rate the beads' (dense kinetic theory: the granular temperature, and with it the
               pressure, goes as d^2 (shear rate)^2 / (1 - e^2))
  np8_linear_dissipation_l4  np8_linear with 1 - e'^2 = l^4 (1 - e^2) (0.97 -> 0.233): the collisional shear
               stress at one shear rate the beads' (the viscosity goes as d sqrt(temperature), so the shear
               stress as d^2 (shear rate)^2 / sqrt(1 - e^2)); fix parcel's `shear_stress 0.97`
  np2_linear_dissipation_l4, np3.375_linear_dissipation_l4, mono_np3.375_linear_dissipation_l4,
  mono_np8_linear_dissipation_l4  the same rule (0.97 -> 0.922 at l = 1.26, 0.837 at l = 1.5, 0.233 at l = 2) for
               np2_linear, np3.375_linear, mono_np3.375_linear and mono_np8_linear
  d2.5mm_linear_dissipation_l4  d2.5mm_linear with the same rule per type pair (0.97 -> 0.738 between the
               small beads' parcels, l = 1.67; 0.875 with the large beads' at the pair's l = 1.41; 0.97 between
               the large ones)
  mono_fine    2 mm beads of one size for both types (the mixture's bed mass), one per parcel: whether what
               coarse graining does to the mixture needs a mixture
  mono_np3.375_linear, mono_np8_linear  3.375 and 8 of those beads per parcel: 3 and 4 mm parcels, scaling
               linear (l = 1.5 and 2)
Every coarse bed has the fine bed's solid mass (to within a parcel), 50/50 by mass. Larger spheres fit less
densely into the insertion region (fix insert/pack places them at random without overlap, and a 5 mm sphere
leaves its centre 7.4 mm of the 12.4 mm wide slot), so the region is made taller until the solid volume over
the volume the centres of the largest parcels can reach is the fine bed's; the filling's viscous force keeps
its terminal velocity, the filling lasts as long per metre of region height and the free settling as long
in seconds as in the fine bed.

DEM step: gas_step / n, n the smallest whole number that gives every variant at least --steps-per-contact DEM
steps per contact of two parcels (t_c = pi/sqrt(kn/m_eff), parcelflow's check, which refuses fewer than 10);
11 gives the shipped case's step (gas step / 12). The gas step is the case's for all variants.

Usage: coarse_graining.py PARCELFLOW OUTPUT_ROOT [--case DIR] [--end T] [--start S] [--ranks N] [--jobs J]
                          [--set KEY=VALUE ...] [--steps-per-contact N] [--restitution E]
                          [--mpirun CMD] [VARIANT ...]
  --case DIR   the fine bed: a folder like this one (default); e.g. a copy with another width or bead count
  --end T      coupled time of every run [s] (default 5); statistics over times in [S, T], --start S (default 1)
  --ranks N    MPI ranks per run (default 2); --jobs J runs at once (default 1: run times stay comparable)
  --mpirun CMD the MPI launcher (default "mpirun"; "-np N" is appended; with several 1-rank --jobs use
               "mpirun --bind-to none": Open MPI binds every 1-rank run to the same first core)
  --set KEY=VALUE  sets a key of the case.yaml copies (dotted path, VALUE in YAML), for every variant, e.g.
               --set coupling.kernel.boundary=reflect --set coupling.kernel.parcel_scale=2; parcel snapshots are
               written after the first gas step and at the end unless output.parcels_interval is set
  --restitution E  the beads' restitution for every pair and the walls (default 0.97, the script's); every
               variant's dampings follow from it
  --steps-per-contact N  the DEM step rule's N (default 11; 22 halves every variant's DEM step, the control
               of whether the scaled contacts are resolved finely enough)
  Each variant runs in OUTPUT_ROOT/VARIANT/ (case copy in case/, run in run/). A variant whose run finished
  with the same case settings, --end and --ranks is not run again; one that stopped after writing checkpoints
  (--set output.checkpoint_interval=T) continues from its newest, so the script can be called again to
  add variants or to rebuild the table. Without VARIANT names: the Goldschmidt comparison, DEFAULT_VARIANTS
  (np3.375_linear, np27_linear and the np8_linear_dissipation variants by name only). The table goes to stdout and to
  OUTPUT_ROOT/coarse_graining.csv.
"""
import argparse
import csv
import glob
import math
import os
import re
import shlex
import shutil
import subprocess
import sys
import time

import h5py
import numpy as np
import yaml

import run_lock  # the folder's own module (sys.path[0] when run, GOLDSCHMIDT when imported by the fluidized set)

HERE = os.path.dirname(os.path.abspath(__file__))

# The beads and contacts of goldschmidt.in; check_script() stops if the script's values disagree.
DENSITY = 2526.0                  # kg/m3, both classes
BEAD_DIAMETERS = (1.5e-3, 2.5e-3)  # types 1 and 2
SPRING = 100.0                    # kn of every type pair [N/m]
RESTITUTION = 0.97                # every type pair
BEAD_FRICTION = 0.10              # bead-bead (variable bead_friction)
FILL_TERMINAL_VELOCITY = 0.3      # m/s of the filling's viscous force, both classes
FREE_STEPS = 1000                 # free settling steps after the filling (at the case's DEM step)
FINE_PARCEL_ARGS = "mode constant_np np 1 scaling none"
FILL_MARGIN, FILL_BOTTOM = 0.0013, 0.002  # the insertion region: margin to the walls, bottom
FILL_REGION = "region          fill block 0.0013 ${fill_x1} 0.0013 ${fill_y1} 0.002 ${fill_top} units box"
GRAVITY = 9.81
COARSE_DIAMETER = 5e-3            # parcel diameter of the d5mm variants
STEPS_PER_CONTACT = 11

# Extra height of the insertion region: random placement without overlap fills it less densely with spheres of
# one size than with the bead mixture (2.5 mm: in the smoke test's third-width bed 3,830 of 3,990 fitted; 2 mm
# beads: in the fluidized periodic box 7,543 of 7,806).
INSERTION_ROOM = {"d2.5mm_linear": 1.15, "d2.5mm_linear_dissipation_l4": 1.15, "mono_fine": 1.15,
                  "mono_np3.375_linear": 1.15, "mono_np3.375_linear_dissipation_l4": 1.15}

# Variants whose parcel-parcel restitution is lowered to 1 - e'^2 = l^k (1 - e^2), by k: k = 1 keeps the fine bed's
# collisional dissipation per unit mass; k = 2 its collisional pressure at one shear rate, k = 4 its collisional
# shear stress (kinetic theory's dense limit: the granular temperature goes as d^2 (shear rate)^2 / (1 - e^2), the
# viscosity as d sqrt(temperature)).
KEEP_DISSIPATION = {"np8_linear_dissipation": 1, "np8_linear_dissipation_friction": 1, "np8_linear_dissipation_l2": 2}
# Variants with k = 4, by fix parcel's keyword `shear_stress` (the beads' restitution; the plugin lowers the
# parcel-parcel restitution to the same e' from the script's dampings and keeps the walls').
SHEAR_STRESS = {"np2_linear_dissipation_l4", "np3.375_linear_dissipation_l4", "np8_linear_dissipation_l4",
                "mono_np3.375_linear_dissipation_l4", "mono_np8_linear_dissipation_l4", "d2.5mm_linear_dissipation_l4"}
# Variants whose parcel-parcel friction is l times the beads': the frictional share of the dissipation too.
SCALE_FRICTION = {"np8_linear_dissipation_friction"}

# Beads of one size for both types: the bed of one particle size, as heavy as the mixture's, that tells whether
# what coarse graining does to the mixture needs a mixture.
MONO_DIAMETER = 2e-3
MONO_BEADS = (MONO_DIAMETER, MONO_DIAMETER)

# name: (description, parcel diameters of types 1 and 2 [m], fix parcel mode, scaling[, bead diameters of types
# 1 and 2, BEAD_DIAMETERS when not given])
VARIANTS = {
    "fine": ("one bead per parcel (the case as shipped)", BEAD_DIAMETERS, "constant_np", "none"),
    "np2_linear": ("2 beads per parcel: 1.89 and 3.15 mm parcels (l = 1.26), scaling linear",
                   tuple(2 ** (1 / 3) * d for d in BEAD_DIAMETERS), "constant_np", "linear"),
    "np3.375_linear": ("3.375 beads per parcel: 2.25 and 3.75 mm parcels (l = 1.5), scaling linear",
                       tuple(1.5 * d for d in BEAD_DIAMETERS), "constant_np", "linear"),
    "np8_linear": ("8 beads per parcel: 3 and 5 mm parcels, scaling linear",
                   tuple(2 * d for d in BEAD_DIAMETERS), "constant_np", "linear"),
    "np27_linear": ("27 beads per parcel: 4.5 and 7.5 mm parcels, scaling linear",
                    tuple(3 * d for d in BEAD_DIAMETERS), "constant_np", "linear"),
    "d5mm_none": ("5 mm parcels of both classes, parcel contact values (scaling none)",
                  (COARSE_DIAMETER, COARSE_DIAMETER), "constant_diameter", "none"),
    "d5mm_linear": ("5 mm parcels of both classes, bead contact values scaled per type pair (scaling linear)",
                    (COARSE_DIAMETER, COARSE_DIAMETER), "constant_diameter", "linear"),
    "d2.5mm_linear": ("2.5 mm parcels of both classes (the largest diameter with 6 parcels across the 15 mm "
                      "depth): small beads 4.63 per parcel, large beads single, scaling linear",
                      (BEAD_DIAMETERS[1], BEAD_DIAMETERS[1]), "constant_diameter", "linear"),
    "d2.5mm_linear_dissipation_l4": ("d2.5mm_linear with parcel-parcel restitution 1 - e'^2 = l^4 (1 - e^2) per "
                                     "type pair", (BEAD_DIAMETERS[1], BEAD_DIAMETERS[1]), "constant_diameter",
                                     "linear"),
    "np8_linear_dissipation": ("np8_linear with parcel-parcel restitution 1 - e'^2 = l (1 - e^2)",
                               tuple(2 * d for d in BEAD_DIAMETERS), "constant_np", "linear"),
    "np8_linear_dissipation_friction": ("np8_linear_dissipation with parcel-parcel friction l mu",
                                        tuple(2 * d for d in BEAD_DIAMETERS), "constant_np", "linear"),
    "np8_linear_dissipation_l2": ("np8_linear with parcel-parcel restitution 1 - e'^2 = l^2 (1 - e^2)",
                                  tuple(2 * d for d in BEAD_DIAMETERS), "constant_np", "linear"),
    "np8_linear_dissipation_l4": ("np8_linear with parcel-parcel restitution 1 - e'^2 = l^4 (1 - e^2)",
                                  tuple(2 * d for d in BEAD_DIAMETERS), "constant_np", "linear"),
    "np2_linear_dissipation_l4": ("np2_linear with parcel-parcel restitution 1 - e'^2 = l^4 (1 - e^2)",
                                  tuple(2 ** (1 / 3) * d for d in BEAD_DIAMETERS), "constant_np", "linear"),
    "np3.375_linear_dissipation_l4": ("np3.375_linear with parcel-parcel restitution 1 - e'^2 = l^4 (1 - e^2)",
                                      tuple(1.5 * d for d in BEAD_DIAMETERS), "constant_np", "linear"),
    "mono_fine": ("2 mm beads of one size for both types, one per parcel", MONO_BEADS, "constant_np", "none",
                  MONO_BEADS),
    "mono_np3.375_linear": ("3.375 of the 2 mm beads per parcel: 3 mm parcels, scaling linear",
                            tuple(1.5 * d for d in MONO_BEADS), "constant_np", "linear", MONO_BEADS),
    "mono_np8_linear": ("8 of the 2 mm beads per parcel: 4 mm parcels, scaling linear",
                        tuple(2 * d for d in MONO_BEADS), "constant_np", "linear", MONO_BEADS),
    "mono_np3.375_linear_dissipation_l4": ("mono_np3.375_linear with parcel-parcel restitution 1 - e'^2 = l^4 "
                                           "(1 - e^2)", tuple(1.5 * d for d in MONO_BEADS), "constant_np", "linear",
                                           MONO_BEADS),
    "mono_np8_linear_dissipation_l4": ("mono_np8_linear with parcel-parcel restitution 1 - e'^2 = l^4 (1 - e^2)",
                                       tuple(2 * d for d in MONO_BEADS), "constant_np", "linear", MONO_BEADS),
}


# The beds of single beads, which the others are compared with.
FINE_VARIANTS = ("fine", "mono_fine")

# What runs without variant names: the fine bed and the coarse beds compared with it in the README.
DEFAULT_VARIANTS = ("fine", "np8_linear", "d5mm_none", "d5mm_linear", "d2.5mm_linear")


def sphere_mass(d):
    return DENSITY * math.pi / 6 * d ** 3


def damping_matrix(masses, parcel_restitution=RESTITUTION, wall_restitution=RESTITUTION):
    """gamman = gammat (mass-specific) of types 1-3: 2 w0 (-ln e)/sqrt(pi^2 + ln^2 e), w0 = sqrt(k/m_eff);
    e = parcel_restitution between parcels, wall_restitution at the wall (type 3: m_eff = the parcel's mass; 3-3
    as 2-3, not used)."""
    def gamma(m_eff, e):
        ln = math.log(e)
        return 2 * math.sqrt(SPRING / m_eff) * -ln / math.sqrt(math.pi ** 2 + ln ** 2)

    m1, m2, e = *masses, parcel_restitution
    pair, wall = gamma(m1 * m2 / (m1 + m2), e), (gamma(m1, wall_restitution), gamma(m2, wall_restitution))
    rows = [[gamma(m1 / 2, e), pair, wall[0]], [pair, gamma(m2 / 2, e), wall[1]], [wall[0], wall[1], wall[1]]]
    return "  ".join(" ".join(f"{g:.6g}" for g in row) for row in rows)


class Plan:
    """What one variant runs: its parcels, DEM step and LIGGGHTS variables, for a fine bed of nbeads."""

    def __init__(self, name, nbeads, gas_step, fine_dem_step, settle_steps, width, depth, height, fill_top,
                 steps_per_contact=STEPS_PER_CONTACT, restitution=RESTITUTION):
        self.name = name
        self.restitution = restitution  # the beads' (every pair and the walls)
        self.description, self.diameters, self.mode, self.scaling, *beads = VARIANTS[name]
        self.beads = beads[0] if beads else BEAD_DIAMETERS
        self.masses = [sphere_mass(d) for d in self.diameters]
        self.np = [(D / d) ** 3 for D, d in zip(self.diameters, self.beads)]
        # 50/50 by mass: parcels per kg of bed are sum 0.5/M over the classes
        fine_mass = nbeads / sum(0.5 / sphere_mass(d) for d in BEAD_DIAMETERS)
        self.parcels = round(fine_mass * sum(0.5 / m for m in self.masses))
        # the kn of each type with itself in force, as parcelflow's contact-time check reads it
        kn = [SPRING * (D / d if self.scaling == "linear" else 1.0) for D, d in zip(self.diameters, self.beads)]
        self.contact_time = min(math.pi / math.sqrt(k / (m / 2)) for k, m in zip(kn, self.masses))
        steps = math.ceil(steps_per_contact * gas_step / self.contact_time - 1e-9)
        self.dem_step = gas_step / steps
        self.steps_per_gas_step = steps
        self.fill_top = self.insertion_top(width, depth, height, fill_top)
        self.variables = {} if name == "fine" else self.coarse_variables(fine_dem_step, settle_steps, fill_top)
        if name == "fine" and restitution != RESTITUTION:  # the script's damping is for RESTITUTION
            self.variables["damping"] = self.damping([sphere_mass(d) for d in self.beads])

    def damping(self, masses, parcel_restitution=None):
        """damping_matrix with the beads' restitution at the walls and, unless given, between parcels."""
        e = self.restitution
        return damping_matrix(masses, e if parcel_restitution is None else parcel_restitution, e)

    def insertion_top(self, width, depth, height, fine_top):
        """Top of the insertion region at which the solid volume over the volume the centres of the largest
        parcels can reach equals the fine bed's (the solid volume is the same)."""
        def reach(radius):  # cross-section the centres can reach, and their lowest height
            return ((width - 2 * FILL_MARGIN - 2 * radius) * (depth - 2 * FILL_MARGIN - 2 * radius),
                    FILL_BOTTOM + 2 * radius)
        (fine_area, fine_low), (area, low) = reach(max(BEAD_DIAMETERS) / 2), reach(max(self.diameters) / 2)
        top = low + (fine_top - fine_low) * fine_area / area * INSERTION_ROOM.get(self.name, 1.0) if area > 0 else math.inf
        if top + max(self.diameters) > height:
            sys.exit(f"{self.name}: parcels of {max(self.diameters) * 1e3:g} mm need an insertion region up to "
                     f"{top:.3g} m in this bed; allowed: up to one parcel diameter below the {height:g} m box")
        return top

    def coarse_variables(self, fine_dem_step, settle_steps, fine_top):
        if self.mode == "constant_np":
            args = f"mode constant_np np {self.np[0]:.12g} scaling {self.scaling}"
        else:
            dp = " ".join(f"{d:.12g}" for d in self.beads)
            args = f"mode constant_diameter diameter {self.diameters[0]:.12g} dp_by_type {dp} none scaling {self.scaling}"
        if self.name in SHEAR_STRESS:
            args += f" shear_stress {self.restitution}"
        # the free settling as long in seconds as the fine bed's, the filling as long per metre of region height
        stretch = fine_dem_step / self.dem_step
        fill_stretch = stretch * (self.fill_top - FILL_BOTTOM) / (fine_top - FILL_BOTTOM)
        variables = {"parcel_args": args, "nbeads": str(self.parcels),
                     "small_radius": f"{self.diameters[0] / 2:.12g}", "large_radius": f"{self.diameters[1] / 2:.12g}",
                     "fill_drag": f"{self.masses[0] * GRAVITY / FILL_TERMINAL_VELOCITY:.6g}",
                     "fill_drag_large_factor": f"{self.masses[1] / self.masses[0]:.6g}",
                     "fill_top": f"{self.fill_top:.4f}", "settle_steps": str(round(settle_steps * fill_stretch)),
                     "free_steps": str(round(FREE_STEPS * stretch))}
        if self.beads != BEAD_DIAMETERS or self.restitution != RESTITUTION:
            # the script's damping is the mixture's beads' at RESTITUTION; these beads' own
            variables["damping"] = self.damping([sphere_mass(d) for d in self.beads])
        if self.scaling == "none":  # parcel values: the beads' spring and restitution with the parcels' masses
            variables["damping"] = self.damping(self.masses)
        l = self.diameters[0] / self.beads[0]  # D / d of the variants that keep the beads' losses
        if self.name in KEEP_DISSIPATION:  # the beads' values for e'; scaling linear keeps e' for the parcels
            restitution = math.sqrt(1 - l ** KEEP_DISSIPATION[self.name] * (1 - self.restitution ** 2))
            variables["damping"] = self.damping([sphere_mass(d) for d in self.beads], restitution)
        if self.name in SCALE_FRICTION:
            variables["bead_friction"] = f"{l * BEAD_FRICTION:.6g}"
        return variables


def script_defaults(script):
    """NAME: VALUE of the script's `variable NAME index VALUE` lines (quotes removed)."""
    found = {}
    for line in open(script):
        m = re.match(r'\s*variable\s+(\S+)\s+index\s+(?:"([^"]*)"|(\S+))', line)
        if m:
            found[m.group(1)] = m.group(2) if m.group(2) is not None else m.group(3)
    return found


def check_script(script):
    """Stops if the script's beads and contacts are not those this file assumes (the coarse values derive
    from them)."""
    text = open(script).read()
    defaults = script_defaults(script)
    bead_masses = [sphere_mass(d) for d in BEAD_DIAMETERS]
    expected = {"small_radius": BEAD_DIAMETERS[0] / 2, "large_radius": BEAD_DIAMETERS[1] / 2,
                "fill_drag": bead_masses[0] * GRAVITY / FILL_TERMINAL_VELOCITY,
                "fill_drag_large_factor": bead_masses[1] / bead_masses[0], "free_steps": FREE_STEPS,
                "bead_friction": BEAD_FRICTION}
    problems = []
    for name, value in expected.items():
        if name not in defaults or abs(float(defaults[name]) / value - 1) > 1e-3:
            problems.append(f"variable {name} = {defaults.get(name)}, expected {value:.6g}")
    damping = [float(v) for v in damping_matrix(bead_masses).split()]
    given = [float(v) for v in defaults.get("damping", "").split()]
    if len(given) != 9 or max(abs(g / d - 1) for g, d in zip(given, damping)) > 1e-4:
        problems.append(f"variable damping = '{defaults.get('damping')}', expected about '{damping_matrix(bead_masses)}'")
    if defaults.get("parcel_args") != FINE_PARCEL_ARGS:
        problems.append(f"variable parcel_args = '{defaults.get('parcel_args')}', expected '{FINE_PARCEL_ARGS}'")
    densities = {float(v) for v in re.findall(r"density constant (\S+)", text)}
    if densities != {DENSITY}:
        problems.append(f"bead densities {sorted(densities)}, expected {DENSITY}")
    if FILL_REGION not in text:
        problems.append(f"no insertion region '{FILL_REGION}'")
    kn = re.search(r"property/global kn peratomtypepair 3 (.*)", text)
    if not kn or {float(v) for v in kn.group(1).split()} != {SPRING}:
        problems.append(f"kn '{kn.group(1) if kn else None}', expected {SPRING} for every pair")
    if problems:
        sys.exit(f"{script} is not the bed coarse_graining.py assumes (edit the constants at its top):\n  " +
                 "\n  ".join(problems))


def set_up(plan, args, config):
    """Copies the fine case into OUTPUT_ROOT/VARIANT/case with the variant's settings; returns the case
    folder and the request that identifies the run."""
    case = os.path.join(args.root, plan.name, "case")
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(args.case, case, ignore=shutil.ignore_patterns("output"))
    config["liggghts"]["variables"].update(plan.variables)
    config["time"]["dem_step"] = plan.dem_step
    if not any(setting.startswith("output.parcels_interval=") for setting in args.set):
        config["output"]["parcels_interval"] = args.end  # one parcel snapshot after the first gas step, one at the end
    with open(os.path.join(case, "case.yaml"), "w") as f:
        yaml.safe_dump(config, f, sort_keys=False)
    return case, {"case": config, "end": args.end, "ranks": args.ranks}


def finished(run, request):
    """Whether run/ holds a finished run of exactly this request."""
    try:
        done = "parcelflow: done:" in open(os.path.join(run, "stdout.txt"), errors="replace").read()
        return done and yaml.safe_load(open(os.path.join(run, "request.yaml"))) == request
    except OSError:
        return False


def newest_checkpoint(run, request):
    """The newest checkpoint of an unfinished run of exactly this request, or None."""
    try:
        if yaml.safe_load(open(os.path.join(run, "request.yaml"))) != request:
            return None
    except OSError:
        return None
    steps = glob.glob(os.path.join(run, "checkpoints", "step_[0-9]*"))
    return max(steps, key=lambda path: int(path.rsplit("_", 1)[1])) if steps else None


def start(plan, case, request, args):
    """Starts the variant's run, or continues it from its newest checkpoint (a run stopped by a signal or
    killed keeps its checkpoints; the wall time of every part is added up in elapsed_s.txt)."""
    run = os.path.join(args.root, plan.name, "run")
    checkpoint = newest_checkpoint(run, request)
    command = shlex.split(args.mpirun) + ["-np", str(args.ranks), args.parcelflow, "run", case, "--output", run,
                                          "--end", str(args.end)]
    if checkpoint:
        print(f"{plan.name}: continuing from {checkpoint}", flush=True)
        command += ["--restart", checkpoint]
        out = open(os.path.join(run, "stdout.txt"), "a")
    else:
        shutil.rmtree(run, ignore_errors=True)
        os.makedirs(run)
        with open(os.path.join(run, "request.yaml"), "w") as f:
            yaml.safe_dump(request, f, sort_keys=False)
        out = open(os.path.join(run, "stdout.txt"), "w")
    return subprocess.Popen(command, stdout=out, stderr=subprocess.STDOUT), time.time(), out


def bed(run):
    """Parcels, np and dp per class and the solid mass (np m_p) from the first parcel snapshot."""
    first = sorted(glob.glob(os.path.join(run, "parcels_[0-9]*.h5")))[0]
    with h5py.File(first, "r") as f:
        dp, np_, kind = np.asarray(f["dp"]).ravel(), np.asarray(f["np"]).ravel(), np.asarray(f["type"]).ravel()
    row = {"parcels": len(dp)}
    for t, cls in ((1, "small"), (2, "large")):
        mine = kind == t
        row[f"parcels_{cls}"] = int(mine.sum())
        row[f"np_{cls}"] = float(np_[mine].mean())
        row[f"np_{cls}_spread"] = float(np_[mine].max() - np_[mine].min())
        row[f"dp_{cls}_mm"] = 1000 * float(dp[mine].mean())
        row[f"D_{cls}_mm"] = 1000 * float((dp[mine] * np.cbrt(np_[mine])).mean())
    row["bed_mass_kg"] = float((np_ * DENSITY * math.pi / 6 * dp ** 3).sum())
    row["largest_parcel_kg"] = float((np_ * DENSITY * math.pi / 6 * dp ** 3).max())
    return row


def summarize(plan, args):
    run = os.path.join(args.root, plan.name, "run")
    rows = list(csv.DictReader(open(os.path.join(run, "monitors.csv"))))
    t = np.array([float(r["time"]) for r in rows])
    window = (t >= args.start - 1e-9) & (t <= args.end + 1e-9)

    def column(key):
        return np.array([float(r[key]) for r in rows])[window]

    small, large = column("mean_z_type1"), column("mean_z_type2")
    stdout = open(os.path.join(run, "stdout.txt"), errors="replace").read()
    contact = re.search(r"parcelflow: DEM step .* = ([0-9.]+) DEM steps", stdout)
    loop = re.search(r"parcelflow: done: .* in ([0-9.]+) s wall", stdout)
    elapsed = os.path.join(run, "elapsed_s.txt")
    row = {"variant": plan.name, "description": plan.description, **bed(run),
           "dem_step_s": plan.dem_step, "steps_per_contact": float(contact.group(1)) if contact else math.nan,
           "window_s": f"{args.start:g}-{args.end:g}", "samples": int(window.sum()),
           "h_small_mm": 1000 * small.mean(), "h_large_mm": 1000 * large.mean(),
           "segregation": (small.mean() - large.mean()) / (0.5 * (small.mean() + large.mean())),
           "rms_small_mm": 1000 * small.std(), "rms_large_mm": 1000 * large.std(),
           "dp_over_weight": column("bed_pressure_drop").mean() / column("bed_weight_per_area").mean(),
           "loop_wall_s": float(loop.group(1)) if loop else math.nan,
           "total_wall_s": float(open(elapsed).read()) if os.path.exists(elapsed) else math.nan}
    return row


def print_table(table):
    """Quantities as rows, variants as columns."""
    keys = [k for k in table[0] if k not in ("variant", "description")]
    width = max(12, *(len(r["variant"]) for r in table))
    print(f"{'':22s}" + "".join(f"{r['variant']:>{width + 2}s}" for r in table))
    for k in keys:
        cells = [r[k] for r in table]
        text = [f"{v:.4g}" if isinstance(v, float) else str(v) for v in cells]
        print(f"{k:22s}" + "".join(f"{c:>{width + 2}s}" for c in text))
    for r in table:
        print(f"  {r['variant']}: {r['description']}")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("parcelflow")
    p.add_argument("root")
    p.add_argument("variants", nargs="*")
    p.add_argument("--case", default=HERE)
    p.add_argument("--end", type=float, default=5.0)
    p.add_argument("--start", type=float, default=1.0)
    p.add_argument("--ranks", type=int, default=2)
    p.add_argument("--jobs", type=int, default=1)
    p.add_argument("--mpirun", default="mpirun")
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE")
    p.add_argument("--steps-per-contact", type=float, default=STEPS_PER_CONTACT)
    p.add_argument("--restitution", type=float, default=RESTITUTION,
                   help="the beads' restitution, every pair and the walls (default: the script's)")
    args = p.parse_intermixed_args()
    if not 0 < args.restitution < 1:
        sys.exit(f"--restitution {args.restitution}: allowed 0 < e < 1")
    args.case = os.path.abspath(args.case)
    args.root = os.path.abspath(args.root)
    names = args.variants or list(DEFAULT_VARIANTS)
    unknown = [n for n in names if n not in VARIANTS]
    if unknown:
        sys.exit(f"unknown variant(s) {unknown}; known: {', '.join(VARIANTS)}")
    if not 0 <= args.start < args.end:
        sys.exit(f"--start {args.start} must lie in [0, --end {args.end})")

    def fine_config():
        config = yaml.safe_load(open(os.path.join(args.case, "case.yaml")))
        for setting in args.set:
            key, sep, value = setting.partition("=")
            if not sep or not key:
                sys.exit(f"--set {setting}: expected KEY=VALUE, e.g. coupling.kernel.parcel_scale=2")
            *parents, leaf = key.split(".")
            node = config
            for name in parents:
                node = node.setdefault(name, {})
            node[leaf] = yaml.safe_load(value)
        return config

    config = fine_config()
    check_script(os.path.join(args.case, config["liggghts"]["script"]))
    variables, times = config["liggghts"]["variables"], config["time"]
    script = os.path.join(args.case, config["liggghts"]["script"])
    depth = float(variables.get("depth", script_defaults(script)["depth"]))
    if abs(depth - config["mesh"]["lengths"][1]) > 1e-9:
        sys.exit(f"the bed's depth {depth:g} m (liggghts.variables.depth) differs from mesh.lengths[1] "
                 f"{config['mesh']['lengths'][1]:g} m")
    plans = [Plan(n, int(variables["nbeads"]), times["gas_step"], times["dem_step"], int(variables["settle_steps"]),
                  float(variables["width"]), depth, float(variables["height"]), float(variables["fill_top"]),
                  args.steps_per_contact, args.restitution)
             for n in names]
    for plan in plans:
        print(f"{plan.name}: {plan.parcels} parcels of {plan.diameters[0] * 1e3:g} / {plan.diameters[1] * 1e3:g} mm, "
              f"np {plan.np[0]:.4g} / {plan.np[1]:.4g}; DEM step {plan.dem_step:.6g} s = gas step / "
              f"{plan.steps_per_gas_step} = t_c / {plan.contact_time / plan.dem_step:.1f} "
              f"(t_c {plan.contact_time:.4g} s); inserted up to {plan.fill_top:.3f} m", flush=True)
        if plan.name == "fine" and abs(plan.dem_step / times["dem_step"] - 1) > 1e-12:
            print(f"  note: the case's own DEM step is {times['dem_step']:.6g} s; the fine run uses the rule's",
                  flush=True)

    run_lock.refuse_if_writing([os.path.join(args.root, plan.name, "run") for plan in plans])
    todo = []
    for plan in plans:
        case, request = set_up(plan, args, fine_config())
        if finished(os.path.join(args.root, plan.name, "run"), request):
            print(f"{plan.name}: finished before, not run again", flush=True)
        else:
            todo.append((plan, case, request))
    running = {}
    failed = []
    while todo or running:
        while todo and len(running) < args.jobs:
            plan, case, request = todo.pop(0)
            running[plan.name] = start(plan, case, request, args)
            print(f"started {plan.name}", flush=True)
        time.sleep(2)
        for name, (proc, t0, out) in list(running.items()):
            if proc.poll() is None:
                continue
            out.close()
            elapsed = time.time() - t0
            print(f"{name}: exit {proc.returncode} after {elapsed:.0f} s", flush=True)
            run = os.path.join(args.root, name, "run")
            with open(os.path.join(run, "elapsed_parts_s.txt"), "a") as parts:
                parts.write(f"{elapsed:.1f}\n")
            if proc.returncode == 0:
                total = sum(float(x) for x in open(os.path.join(run, "elapsed_parts_s.txt")))
                open(os.path.join(run, "elapsed_s.txt"), "w").write(f"{total:.1f}\n")
            else:
                failed.append(name)
                print(f"{name} failed; its output: {os.path.join(run, 'stdout.txt')}", flush=True)
            del running[name]

    table = [summarize(plan, args) for plan in plans if plan.name not in failed]
    if not table:
        sys.exit("no finished run to tabulate")
    for r in table:
        log = os.path.join(args.root, r["variant"], "run", "log.liggghts")
        if os.path.exists(log) and "Less insertions than requested" in open(log, errors="replace").read():
            print(f"warning: {r['variant']}: LIGGGHTS inserted fewer parcels than requested ({log}): its bed is "
                  "lighter than the others (mass_vs_fine_parcels)", flush=True)
    fine = next((r for r in table if r["variant"] in FINE_VARIANTS), None)
    for r in table:  # solid mass against the (first) fine bed's, in parcels of the variant's largest parcel
        r["mass_vs_fine_parcels"] = ((r["bed_mass_kg"] - fine["bed_mass_kg"]) / r["largest_parcel_kg"]
                                     if fine else math.nan)
    path = os.path.join(args.root, "coarse_graining.csv")
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(table[0]))
        writer.writeheader()
        writer.writerows(table)
    print_table(table)
    print(f"table written: {path}")
    if failed:
        sys.exit(f"failed: {', '.join(failed)}")


if __name__ == "__main__":
    main()
