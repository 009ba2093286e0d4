"""Problems that used to show only in the closing summary are reported when they start: parcels whose centre is
in no fluid cell (some or all, at the first coupling step, with their number and an example position), no
parcel at all (exit code 2), parcels lost under `thermo_modify lost ignore` (at the step the count drops, up to
"every parcel is lost"), parcels outside case.yaml's geometry (its walls and LIGGGHTS' disagree), linear solves that stop at max_iterations (the first step, then every 100th such
step) and a pressure solve that does no iteration."""
import re

from reliability_runs import GAS_STEP, PARCELS, expect, fail, falling_bed, main

NO_GUARDS = {"max_cfl": 1e300, "max_continuity_error": 1e300, "max_parcel_loss": 1.0}


def first_step_of(text, words):
    """The step number of the first warning line containing words; fails if there is none."""
    line = next((l for l in text.splitlines() if "warning" in l and words in l), None)
    if line is None:
        fail(f"no warning with '{words}'\n{text[-3000:]}")
    return int(re.search(r"\(step (\d+)\)", line).group(1)) if "(step" in line else 1


def parcels_outside_the_mesh(runs):
    some = runs.case(lambda s: s["mesh"].update(origin=[0.01, 0, 0]))  # the mesh covers x > 0.01 only
    text = expect("half the bed outside the mesh", runs.run(some), 0, "have their centre in no fluid cell",
                  "at the first coupling step")
    count = int(re.search(r"warning: (\d+) of (\d+) parcels", text).group(1))
    if not 0.2 * PARCELS < count < 0.8 * PARCELS:
        fail(f"{count} of {PARCELS} parcels reported outside, expected about half")
    everything = runs.case(lambda s: s["mesh"].update(origin=[1.0, 1.0, 0.0]))
    expect("the whole bed outside the mesh", runs.run(everything), 0, f"all: {PARCELS} of {PARCELS} parcels")


def parcels_outside_the_geometry(runs):
    def narrower(s):  # a column of radius 6 mm in the 20 mm box the LIGGGHTS walls fill
        s["geometry"] = [{"shape": {"cylinder": {"center": [0.01, 0.01], "radius": 0.006, "zmin": 0.0, "zmax": 0.1}}}]
        s["boundaries"]["walls"] = {"type": "wall"}
        for side in ("xmin", "xmax", "ymin", "ymax"):  # the box's sides are all solid now
            del s["boundaries"][side]
    text = expect("a gas column narrower than the LIGGGHTS walls", runs.run(runs.case(narrower)), 0,
                  "have their centre outside case.yaml's geometry", "disagree")
    count = int(re.search(r"warning: (\d+) of (\d+) parcels have their centre outside", text).group(1))
    # staircase: the 3 x 3 cells of 4 mm whose centres are inside hold the circle and 7.7 % of the box outside it
    if not 0.02 * PARCELS < count < 0.2 * PARCELS:
        fail(f"{count} of {PARCELS} parcels reported outside the geometry, expected about 8 %")
    print(f"[measured] {count} of {PARCELS} parcels outside the geometry's cylinder in fluid cells")

    def whole_box(s):
        s["geometry"] = [{"shape": {"box": {"min": [0.0, 0.0, 0.0], "max": [0.02, 0.02, 0.1]}}}]
    rc, text, _ = runs.run(runs.case(whole_box))
    if rc != 0 or "outside case.yaml's geometry" in text:
        fail(f"a geometry that is the LIGGGHTS box: exit {rc} or a warning\n{text[-2000:]}")


def no_parcels(runs):
    case = runs.case(script=lambda t: t.replace("run             2000\n",
                                                "run             2000\ndelete_atoms group all\n"))
    expect("a script that leaves no parcel", runs.run(case), 2, "liggghts.script", "at least one parcel")


def every_parcel_lost(runs):
    def edit(s):
        s["boundaries"]["zmin"]["superficial_velocity"] = [0, 0, 0]
        s["coupling"]["guards"] = NO_GUARDS
    result = runs.run(runs.case(edit, falling_bed), end=500 * GAS_STEP)
    text = expect("the bed falls out through z = 0", result, 0, "parcels lost in the last DEM advance",
                  "every parcel is lost")
    first, last = first_step_of(text, "parcels lost"), first_step_of(text, "every parcel is lost")
    if not 1 < first <= last < 500:
        fail(f"losses reported from step {first} to {last}")
    print(f"[measured] first loss reported at step {first}, the last parcel at step {last}")


def solver_trouble(runs):
    def unconverged(s):
        s["solver"]["pressure"] = {"preconditioner": "jacobi", "max_iterations": 2}
        s["coupling"]["guards"] = NO_GUARDS
    text = expect("pressure solves stopped at 2 iterations", runs.run(runs.case(unconverged), end=200 * GAS_STEP),
                  0, "stopped at max_iterations")
    steps = [int(m) for m in re.findall(r"\(step (\d+)\): \d+ linear solves stopped", text)]
    if steps != [1, 101]:
        fail(f"unconverged solves reported at steps {steps}, expected [1, 101]")

    def loose(s):
        s["solver"]["pressure"].update(criterion="strict", absolute_tolerance=1e10)
        s["coupling"]["guards"] = NO_GUARDS
    text = expect("absolute_tolerance 1e10", runs.run(runs.case(loose)), 0, "did no iteration",
                  "absolute_tolerance = 1e+10")
    if first_step_of(text, "did no iteration") != 1:
        fail("the pressure solve without iterations must be reported at the first step")


if __name__ == "__main__":
    main([parcels_outside_the_mesh, parcels_outside_the_geometry, no_parcels, every_parcel_lost, solver_trouble])
