"""Inputs that used to run on silently or mislead now stop with exit code 2 naming the key, the value and what
is allowed (a duplicated key in case.yaml with both lines, gas_step > end, a gas step of 2^32 DEM steps, a
liggghts.variables entry that parcelflow sets itself, a count that LIGGGHTS would read as its leading digits),
and a fresh run in a folder that holds an earlier run's output says so at the start and removes that run's
snapshots, XDMF indexes and checkpoints, so that every snapshot file in the folder is one the new XDMF lists. A continued run (--restart) leaves them in place."""
import glob
import os
import re

from reliability_runs import GAS_STEP, expect, fail, main


def duplicated_key(runs):
    case = runs.case()
    path = os.path.join(case, "case.yaml")
    lines = open(path).read().splitlines()
    first = next(n for n, l in enumerate(lines, 1) if l.strip().startswith("density:"))
    lines.insert(first, lines[first - 1].replace("1.2", "1.3"))
    open(path, "w").write("\n".join(lines) + "\n")
    expect("gas.density given twice", runs.run(case), 2, "gas.density is given twice",
           f"lines {first} and {first + 1}")


def time_settings(runs):
    expect("gas_step > end", runs.run(runs.case(lambda s: s["time"].update(end=GAS_STEP / 2)), end=None), 2,
           "time.gas_step", "gas_step <= end")
    huge = 2 ** 32 * 2.0e-5
    expect("gas step of 2^32 DEM steps", runs.run(runs.case(lambda s: s["time"].update(gas_step=huge, end=huge)),
                                                  end=None), 2, "time.gas_step", "at most 1e6 DEM steps")
    expect("liggghts.variables.dem_step", runs.run(runs.case(lambda s: s["liggghts"]["variables"].update(
        dem_step="1e-5"))), 2, "liggghts.variables.dem_step", "parcelflow sets dem_step itself")
    expect("liggghts.variables.geometry_stl", runs.run(runs.case(lambda s: s["liggghts"]["variables"].update(
        geometry_stl="walls.stl"))), 2, "liggghts.variables.geometry_stl", "parcelflow sets geometry_stl itself")


def counts_not_written_in_digits(runs):
    """LIGGGHTS reads `particles_in_region` and `run` counts with atoi / atoll, which take the leading digits:
    nparcels "1e300" inserted 1 parcel and ran on."""
    script = os.path.join(runs.case(), "column.in")
    line = next(n for n, l in enumerate(open(script), 1) if l.startswith("fix  insert"))  # continued below
    for value in ("1e300", "1146.0", "1e3", "99999999999"):
        expect(f"nparcels = {value}", runs.run(runs.case(lambda s: s["liggghts"]["variables"].update(
            nparcels=value))), 2, f"liggghts.variables.nparcels = {value}", "a whole number written in digits",
            f"column.in line {line}", "particles_in_region")

    def run_variable(text):
        return text.replace("run             2000", "run             ${relax}")
    case = runs.case(lambda s: s["liggghts"]["variables"].update(relax="2e3"), script=run_variable)
    expect("run ${relax} with relax = 2e3", runs.run(case), 2, "liggghts.variables.relax = 2e3", "`run`")


def snapshots(out):
    return sorted(os.path.basename(p) for p in glob.glob(os.path.join(out, "*_[0-9]*.h5")))


def listed(out):
    names = []
    for index in glob.glob(os.path.join(out, "*.xdmf")):
        names += re.findall(r"([a-z]+_[0-9]+\.h5):", open(index).read())
    return sorted(set(names))


def earlier_run_in_the_folder(runs):
    every_step = {"fields_interval": GAS_STEP, "parcels_interval": GAS_STEP, "checkpoint_interval": 5 * GAS_STEP}
    case = runs.case(lambda s: s["output"].update(every_step))
    rc, text, out = runs.run(case)
    if rc != 0 or len(snapshots(out)) != 20 or not os.path.isdir(os.path.join(out, "checkpoints")):
        fail(f"the first run should leave 10 field and 10 parcel snapshots and checkpoints: {snapshots(out)}\n{text}")
    old_checkpoint = sorted(glob.glob(os.path.join(out, "checkpoints", "step_*")))[-1]
    # A continued run keeps the series and appends to it.
    rc, text, _ = runs.run(case, "--restart", old_checkpoint, end=15 * GAS_STEP, output=out)
    if rc != 0 or "earlier run" in text or len(snapshots(out)) != 30:
        fail(f"a continued run must leave the earlier output in place: {snapshots(out)}\n{text}")
    # A fresh run with snapshots only at the end.
    fresh = runs.case()
    result = runs.run(fresh, end=3 * GAS_STEP, output=out)
    text = expect("a fresh run in an earlier run's folder", result, 0, "held an earlier run's output",
                  "moved 30 snapshot files", "checkpoints/", "parcels.xdmf", "earlier_run_1")
    if text.index("held an earlier run's output") > text.index("parcelflow: done"):
        fail("the warning must come at the start")
    if snapshots(out) != listed(out) or snapshots(out) != ["fields_000000.h5"]:
        fail(f"the folder holds {snapshots(out)}, the XDMF indexes list {listed(out)}")
    if os.path.exists(os.path.join(out, "checkpoints")) or os.path.exists(os.path.join(out, "parcels.xdmf")):
        fail("the earlier run's checkpoints and parcels.xdmf must have been moved aside")
    aside = os.path.join(out, "earlier_run_1")
    if len(glob.glob(os.path.join(aside, "*_0*.h5"))) != 30 or not os.path.isdir(os.path.join(aside, "checkpoints")) \
            or not os.path.exists(os.path.join(aside, "monitors.csv")):
        fail(f"the earlier run's files are not all in {aside}: {sorted(os.listdir(aside))}")
    print(f"[measured] after the fresh run the folder holds {snapshots(out)}, listed by the XDMF: {listed(out)}")


if __name__ == "__main__":
    main([duplicated_key, time_settings, counts_not_written_in_digits, earlier_run_in_the_folder])
