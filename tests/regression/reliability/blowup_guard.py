"""The blow-up guard (coupling/run/blowup_guard.h) stops a run whose gas Courant number, continuity error or
parcel loss in one step exceeds coupling.guards' limits, with exit code 3 and a message naming the quantity,
its limit, where (the cell centre of the fastest gas) and when (time, gas step), before that step's outputs: the
newest checkpoint is the one of the step before, complete and readable. Cases: an absurd gas step (250 DEM
steps, 2 mm cells, gas-fraction floor 0.01, the column's 1146 parcels) passes the default max_cfl = 1000 in
its first step; limits set below what the column reaches (its Courant number rises from 0.113 to 0.115 in
the first 10 steps, its continuity error is about 1e-9) stop it at a known step; a bed falling out of the
column loses more than 5 % of its parcels in one step."""
import glob
import os
import re

import h5py

from reliability_runs import GAS_STEP, expect, fail, falling_bed, main


def step_of(text):
    return int(re.search(r"diverged at t = [0-9.e+-]+ s \(gas step (\d+)\)", text).group(1))


def absurd_gas_step(runs):
    def edit(s):
        s["liggghts"]["variables"]["nparcels"] = "1146"  # the column's full bed
        s["time"]["gas_step"] = 250 * s["time"]["dem_step"]
        s["mesh"]["cells"] = [10, 10, 50]
        s["coupling"].update(gas_fraction_floor=0.01, kernel={"type": "centroid"})
    text = expect("gas step of 250 DEM steps", runs.run(runs.case(edit), end=10 * 250 * 2e-5), 3,
                  "gas Courant number", "coupling.guards.max_cfl = 1000", "at cell centre")
    if step_of(text) != 1:
        fail("expected the stop in the first gas step")


def checkpoint_before(runs):
    def edit(s):
        s["coupling"]["guards"] = {"max_cfl": 0.114}
        s["output"]["checkpoint_interval"] = GAS_STEP
    result = runs.run(runs.case(edit))
    text = expect("max_cfl 0.114 with a checkpoint every step", result, 3, "gas Courant number",
                  "coupling.guards.max_cfl = 0.114", "the last good checkpoint is")
    step = step_of(text)
    folders = sorted(glob.glob(os.path.join(result[2], "checkpoints", "*step_*")))
    newest = folders[-1]
    if not 1 < step <= 10 or os.path.basename(newest) != f"step_{step - 1:09d}" or newest not in text:
        fail(f"stopped at gas step {step}; checkpoints {folders}")
    with h5py.File(os.path.join(newest, "gas.h5"), "r") as gas:
        ids = list(gas.keys())
    if not os.path.isfile(os.path.join(newest, "loop.yaml")) or not ids:
        fail(f"{newest} is not complete")
    print(f"[measured] stopped at gas step {step}; newest checkpoint {os.path.basename(newest)} (gas.h5: {ids})")


def continuity(runs):
    def edit(s):
        s["coupling"]["guards"] = {"max_continuity_error": 1e-12}
    expect("max_continuity_error 1e-12", runs.run(runs.case(edit)), 3, "continuity error",
           "coupling.guards.max_continuity_error = 1e-12")


def sudden_parcel_loss(runs):
    def edit(s):
        s["boundaries"]["zmin"]["superficial_velocity"] = [0, 0, 0]
        s["coupling"]["guards"] = {"max_parcel_loss": 0.05}
    result = runs.run(runs.case(edit, falling_bed), end=500 * GAS_STEP)
    expect("bed falling out, max_parcel_loss 0.05", result, 3,
           "parcels lost in one coupling step", "coupling.guards.max_parcel_loss = 0.05")


if __name__ == "__main__":
    main([absurd_gas_step, checkpoint_before, continuity, sudden_parcel_loss])
