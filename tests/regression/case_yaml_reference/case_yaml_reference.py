#!/usr/bin/python3
"""cases/case_yaml_reference.md holds every key of case.yaml, and only keys the program accepts.

Documented => accepted: two generated cases (below) together hold every documented key, each with a value from
its documented range; the set of their key paths must equal the reference's keys, and `parcelflow run` must
read each of them to the end (it is then stopped by `--end 1e-12`, shorter than one gas step: exit 2 naming
--end, after case.yaml was read and checked completely, before any work).
Accepted => documented: into every map of those cases a key `zz_probe` is put, one at a time; the program's
error lists the keys allowed there ("allowed here: ..." or, for a shape, "one of: ..."), and each must be in
the reference under that map's path. Maps of free names (boundaries, liggghts.variables) are not probed.
Every shipped case.yaml is read the same way and its keys must be documented.

usage: case_yaml_reference.py PARCELFLOW REPOSITORY"""
import copy
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

import yaml

SHAPE_PLACES = ("geometry[].shape", "inlet_regions[].region[].shape", "mesh.partition_weights[].region")
FREE_NAMES = {"boundaries": "<patch>", "liggghts.variables": "<name>"}


def box(lo, hi):
    return {"box": {"min": lo, "max": hi}}


# Every documented key with a value from its range. Mutually exclusive keys go into the second case.
CASE_A = {
    "liggghts": {"script": "bed.in", "variables": {"np": "8"}},
    "time": {"end": 0.01, "gas_step": 1.0e-4, "dem_step": 1.0e-5},
    "coupling": {"drag": "WenYu",
                 "kernel": {"type": "gaussian", "sharpness": 1.0, "radius": 2, "length_scale": "cell_axes",
                            "parcel_scale": 1.0, "boundary": "reflect", "smoothing_length": 0.001},
                 "gas_fraction_floor": 0.3, "excess_solids": "discard",
                 "class_collisions": {"restitution": 0.9, "friction": 0.3},
                 "guards": {"max_cfl": 100.0, "max_continuity_error": 0.5, "max_parcel_loss": 0.5}},
    "output": {"folder": "out", "monitor_interval": 0.002, "progress_interval": 5, "fields_interval": 0.01,
               "parcels_interval": 0, "checkpoint_interval": 0.01},
    "monitors": {"pressure_planes": [0.001, 0.01], "bed_pressure_drop": [0.001, 0.02], "average": {"start": 0.0}},
    "mesh": {"origin": [-0.03, -0.03, 0.0], "lengths": [0.06, 0.06, 0.15], "cells": [12, 12, 30],
             "ghost_layers": 2, "walls": "cut_cells", "small_cell_fraction": 0.01,
             "partition_weights": [{"region": box([-0.03, -0.03, 0.0], [0.03, 0.03, 0.05]), "weight": 2}]},
    "geometry": [
        {"op": "union", "shape": {"stl": {"file": "vessel.stl"}}},
        {"shape": {"cylinder": {"center": [0, 0], "radius": 0.02, "zmin": 0.0, "zmax": 0.1}}},
        {"shape": {"cone": {"center": [0, 0], "radius_zmin": 0.02, "radius_zmax": 0.01, "zmin": 0.1, "zmax": 0.15}}},
        {"op": "cut", "shape": box([-0.005, -0.005, 0.05], [0.005, 0.005, 0.06]), "patch": "tube"}],
    "gas": {"density": 1.2, "viscosity": 1.8e-5, "gravity": [0, 0, -9.81]},
    "boundaries": {"zmin": {"type": "velocity_inlet", "superficial_velocity": [0, 0, 0.5], "ramp_time": 0.01,
                            "distributor_pressure_drop": 100.0},
                   "zmax": {"type": "pressure_outlet", "pressure": 0.0},
                   "walls": {"type": "wall", "slip": "free_slip"},
                   "tube": {"type": "wall"}},
    "inlet_regions": [{"name": "ring", "flow_rate": 1e-5, "velocity": [0, 0, 0.1], "ramp_time": 0.01,
                       "region": [{"op": "union", "shape": {"cylinder": {"center": [0, 0], "radius": 0.01,
                                                                         "zmin": 0.01, "zmax": 0.015}}},
                                  {"op": "cut", "shape": {"cylinder": {"center": [0, 0], "radius": 0.005,
                                                                       "zmin": 0.01, "zmax": 0.015}},
                                   "patch": "unused"}]}],
    "solver": {"piso_correctors": 2, "convection": "upwind",
               "pressure": {"criterion": "normalized", "tolerance": 1e-6, "rel_tol": 0.05, "final_rel_tol": 0.0,
                            "max_iterations": 1000, "preconditioner": "block_ic", "preconditioner_reuse": 20},
               "momentum": {"criterion": "normalized", "tolerance": 1e-5, "rel_tol": 0.1, "max_iterations": 1000,
                            "preconditioner": "jacobi"}},
}
CASE_B = copy.deepcopy(CASE_A)
CASE_B["coupling"] = {"drag": "RadlSundaresanFilteredBVK",
                      "filtered_drag": {"particle_density": 2500.0, "filter_cells": 2.0}}
CASE_B["solver"] = {"pressure": {"criterion": "strict", "tolerance": 1e-8, "absolute_tolerance": 1e-30},
                    "momentum": {"criterion": "strict", "tolerance": 1e-8, "absolute_tolerance": 1e-30}}


def documented_keys(reference):
    keys = [m.group(1) for m in re.finditer(r"^\| `([^`]+)` \|", open(reference).read(), re.M)]
    duplicates = {k for k in keys if keys.count(k) > 1}
    if duplicates:
        sys.exit(f"FAIL: {reference} documents these keys twice: {sorted(duplicates)}")
    return set(keys)


def normalized(path):
    """The reference's name of a key path: list items as [], free names as <patch>/<name>, shapes as <shape>."""
    for place in SHAPE_PLACES:
        if path.startswith(place + "."):
            return "<shape>" + path[len(place):]
    for parent, name in FREE_NAMES.items():
        if path.startswith(parent + "."):
            rest = path[len(parent) + 1:].split(".", 1)
            return parent + "." + name + ("." + rest[1] if len(rest) > 1 else "")
    return path


def key_paths(node, path=""):
    """Every key path of a parsed case.yaml (list items as [])."""
    if isinstance(node, dict):
        for key, value in node.items():
            child = f"{path}.{key}" if path else str(key)
            yield child
            yield from key_paths(value, child)
    elif isinstance(node, list) and any(isinstance(item, dict) for item in node):
        for item in node:
            yield from key_paths(item, path + "[]")


def maps(node, path=""):
    """(path, dict) of every map of the case, itself included."""
    if isinstance(node, dict):
        yield path, node
        for key, value in node.items():
            yield from maps(value, f"{path}.{key}" if path else str(key))
    elif isinstance(node, list):
        for item in node:
            yield from maps(item, path + "[]")


class Runner:
    def __init__(self, parcelflow, repo, work):
        self.parcelflow, self.work, self.count, self.wrote_output = parcelflow, work, 0, False
        self.stl = os.path.join(repo, "cases", "stl_vessel", "vessel.stl")

    def read(self, settings):
        """Exit code and message of `parcelflow run` stopped by --end 1e-12: on a case folder (a shipped case,
        read in place; nothing is written before --end is checked) or on a new one holding these settings."""
        self.count += 1
        case = os.path.join(self.work, f"case{self.count}")
        if isinstance(settings, str):
            folder = settings
        else:
            folder = case
            os.makedirs(case)
            yaml.safe_dump(settings, open(os.path.join(case, "case.yaml"), "w"))
            open(os.path.join(case, "bed.in"), "w").write("# never run: the case stops at --end\n")
            shutil.copy(self.stl, case)
        done = subprocess.run([self.parcelflow, "run", folder, "--end", "1e-12", "--output", os.path.join(case, "o")],
                              capture_output=True, text=True, errors="replace", timeout=60)
        if os.path.exists(os.path.join(case, "o")):
            self.wrote_output = True
        shutil.rmtree(case, ignore_errors=True)
        return done.returncode, done.stderr.strip()


def read_to_the_end(runner, settings, name, failures):
    code, message = runner.read(settings)
    if code != 2 or "--end" not in message:
        failures.append(f"{name} was not read to the end (exit {code}): {message[-600:]}")
    else:
        print(f"OK {name} read completely")


def allowed_lists(runner, settings, skip, failures):
    """(normalized map path, keys the program allows there) for every map path of the case not in `skip`: a key
    `zz_probe` put into every map of that path makes the program list the keys allowed there."""
    for path in dict.fromkeys(p for p, _ in maps(settings)):
        if path in FREE_NAMES or path in skip:
            continue
        skip.add(path)
        probe = copy.deepcopy(settings)
        for p, node in maps(probe):
            if p == path:
                node["zz_probe"] = 1
        code, message = runner.read(probe)
        found = re.search(r"allowed here: (.*)$", message) or \
            re.search(r"must have exactly one key, one of: (.*)$", message)
        if code != 2 or not found:
            failures.append(f"probe of {path or 'the top level'}: exit {code}, {message[-400:]}")
            continue
        yield ("<shape>" if path in SHAPE_PLACES else normalized(path)), [k.strip() for k in found.group(1).split(",")]


def main():
    parcelflow, repo = sys.argv[1], sys.argv[2]
    reference = os.path.join(repo, "cases", "case_yaml_reference.md")
    documented = documented_keys(reference)
    failures = []
    work = tempfile.mkdtemp(prefix="pf_case_keys_")
    try:
        runner = Runner(os.path.abspath(parcelflow), repo, work)
        generated = {normalized(p) for case in (CASE_A, CASE_B) for p in key_paths(case)}
        for key in sorted(documented - generated):
            failures.append(f"documented but not in the generated cases (give it a value in this test): {key}")
        for key in sorted(generated - documented):
            failures.append(f"in the generated cases but not documented: {key}")
        read_to_the_end(runner, CASE_A, "generated case A", failures)
        read_to_the_end(runner, CASE_B, "generated case B", failures)
        probed = set()
        for case in (CASE_A, CASE_B):
            for path, allowed in allowed_lists(runner, case, probed, failures):
                for key in allowed:
                    if (f"{path}.{key}" if path else key) not in documented:
                        failures.append(f"accepted by the program but not documented: {path}.{key}".replace(" .", " "))
        for case_yaml in sorted(glob.glob(os.path.join(repo, "cases", "**", "case.yaml"), recursive=True)):
            name = os.path.relpath(os.path.dirname(case_yaml), repo)
            for key in sorted({normalized(p) for p in key_paths(yaml.safe_load(open(case_yaml)))} - documented):
                failures.append(f"{name}/case.yaml uses the undocumented key {key}")
            read_to_the_end(runner, os.path.dirname(case_yaml), name, failures)
        if runner.wrote_output:
            failures.append("a case stopped by --end wrote its output folder")
        print(f"{len(documented)} documented keys; {len(probed)} maps probed; {runner.count} cases read")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    failures = sorted(set(failures))
    print("\n".join(failures) if failures else "case_yaml_reference: OK")
    sys.exit(1 if failures or os.path.exists(work) else 0)


main()
