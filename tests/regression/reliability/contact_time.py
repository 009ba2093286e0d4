"""The DEM step against the contact time (coupling/dem/contact_time_check.h): parcelflow prints its estimate for
the case's contact model and smallest parcel, which agrees with the formula computed here, and a DEM step
above t_c/10 stops with exit code 2 naming time.dem_step, the estimate and the limit, for hooke/stiffness (the
column's kn, scaled by `fix parcel ... scaling linear`) and for hertz (Young's modulus, Poisson ratio, 1 m/s).
A DEM step of 0.55 t_c, with which LIGGGHTS lost atoms in the script's own settling before the check moved
into fix parcel/implicit_drag's init, stops at the start of the settling run, in `parcelflow run` (naming
time.dem_step) and in `parcelflow dem` (naming the script's timestep), with no "Lost atoms"."""
import math
import os
import re
import subprocess

from reliability_runs import GAS_STEP, expect, fail, main

BEAD_DIAMETER, NP, DENSITY = 1e-3, 8, 2500.0
RADIUS = 0.5 * BEAD_DIAMETER * NP ** (1 / 3)  # the parcel's collision radius (the script's ${radius})
MASS = DENSITY * 4 / 3 * math.pi * RADIUS ** 3
YOUNG, POISSON = 5e6, 0.3


def hooke_contact_time():
    k = 50.0 * (2 * RADIUS / BEAD_DIAMETER)  # kn of column.in times l = D/dp (scaling linear)
    return math.pi / math.sqrt(k / (MASS / 2))


def hertz_contact_time():
    e_eff = YOUNG / (2 * (1 - POISSON ** 2))
    return 2.87 * ((MASS / 2) ** 2 / (RADIUS / 2 * e_eff ** 2 * 1.0)) ** 0.2


def hertz(text):
    """column.in with Hertz contacts of Young's modulus YOUNG instead of the Hooke stiffness."""
    text = re.sub(r"fix  (kn|kt|gn|gt)  all property/global .*\n", "", text)
    text = text.replace("fix  mu  all", f"fix  E all property/global youngsModulus peratomtype {YOUNG} {YOUNG}\n"
                        f"fix  nu all property/global poissonsRatio peratomtype {POISSON} {POISSON}\n"
                        "fix  e all property/global coefficientRestitution peratomtypepair 2 0.9 0.9 0.9 0.9\n"
                        "fix  mu  all")
    return text.replace("hooke/stiffness", "hertz").replace("scaling linear", "scaling none")


def printed_contact_time(text):
    return float(re.search(r"contact time ([0-9.e+-]+) s", text).group(1))


def check_model(runs, name, script, expected):
    text = expect(f"{name}: default DEM step", runs.run(runs.case(script=script)), 0, "contact time")
    printed = printed_contact_time(text)
    print(f"[measured] {name}: contact time {printed:.4g} s printed, {expected:.4g} s from the formula here")
    if abs(printed - expected) > 0.01 * expected:
        fail(f"{name}: contact time {printed} s, expected {expected} s")
    dem_step = GAS_STEP / 5 if expected / (GAS_STEP / 5) < 10 else GAS_STEP / 2
    if expected / dem_step >= 10:
        fail(f"{name}: no DEM step divides the gas step and exceeds t_c/10")
    big = runs.case(lambda s: s["time"].update(dem_step=dem_step), script)
    expect(f"{name}: DEM step {dem_step:g} s = t_c/{expected / dem_step:.1f}", runs.run(big), 2, "time.dem_step",
           "t_c/10", "DEM steps per contact")


def stops_before_settling(runs):
    """The settling run of column.in starts at DEM step 1 (after `run 1` inserted the parcels)."""
    step = 4e-4  # = 0.55 t_c; also the gas step, so that the case is otherwise valid
    case = runs.case(lambda s: s["time"].update(dem_step=step, gas_step=step))
    text = expect(f"run: DEM step {step:g} s", runs.run(case, end=10 * step), 2, "time.dem_step",
                  "found at the start of a LIGGGHTS run at DEM step 1", "t_c/10")
    if "Lost atoms" in text:
        fail(f"run: LIGGGHTS lost atoms before the check\n{text[-2000:]}")
    # the same script under `parcelflow dem`, with the variables parcelflow passes to it
    variables = {"dem_step": repr(step), "restarting": "0", "restart_file": "none", "np": "8", "radius": "0.001",
                 "nparcels": str(300), "skin": "0.0004"}
    command = runs.launcher + [os.path.abspath(runs.parcelflow), "dem", "column.in", "-log", "none"]
    for name, value in variables.items():
        command += ["-var", name, value]
    done = subprocess.run(command, cwd=case, capture_output=True, text=True, errors="replace", timeout=300,
                          env=runs.env)
    text = expect(f"dem: timestep {step:g} s", (done.returncode, done.stdout + done.stderr, None), 2,
                  "error in script 'column.in': timestep", "at the start of the run at step 1", "t_c/10")
    if "Lost atoms" in text:
        fail(f"dem: LIGGGHTS lost atoms before the check\n{text[-2000:]}")


if __name__ == "__main__":
    main([lambda runs: check_model(runs, "hooke/stiffness", lambda t: t, hooke_contact_time()),
          lambda runs: check_model(runs, "hertz", hertz, hertz_contact_time()),
          stops_before_settling])
