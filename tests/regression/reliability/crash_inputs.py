"""Inputs that used to crash (uncaught exceptions, segfaults, aborts) now stop with a message naming the key or
file, the value and what is allowed: exit code 2 for user errors, before any work (also where LIGGGHTS stops on
an error one rank found); a non-finite parcel value
found during the run stops all ranks with the parcel's id, the value and the time (exit code != 0)."""
import os

from reliability_runs import expect, main


def unwritable_output(runs):
    case = runs.case()
    for folder in ("/proc/pf_reliability_x", "/dev/null/x"):
        expect(f"--output {folder}", runs.run(case, output=folder), 2, "--output", folder, "can be created")


def case_yaml_is_a_folder(runs):
    case = runs.case()
    os.remove(os.path.join(case, "case.yaml"))
    os.mkdir(os.path.join(case, "case.yaml"))
    expect("case.yaml that is a folder", runs.run(case), 2, "case.yaml", "readable file")


def script_that_is_a_folder_or_empty(runs):
    """Both used to pass to LIGGGHTS, which read nothing; the first message was about its default timestep."""
    case = runs.case()
    os.remove(os.path.join(case, "column.in"))
    os.mkdir(os.path.join(case, "column.in"))
    expect("liggghts.script that is a folder", runs.run(case), 2, "liggghts.script = column.in", "a readable file")
    case = runs.case(script=lambda text: "")
    expect("empty liggghts.script", runs.run(case), 2, "liggghts.script = column.in", "is empty")


def end_below_one_gas_step(runs):
    expect("--end 1e-300", runs.run(runs.case(), end=1e-300), 2, "--end", "1e-300", "at least one gas step")


def values_the_solver_cannot_honour(runs):
    cases = [("mesh.cells [100000]^3", lambda s: s["mesh"].update(cells=[100000] * 3), ["mesh.cells", "1e8"]),
             ("gas.density 1e-300", lambda s: s["gas"].update(density=1e-300), ["gas.density", "[0.001, 10000]"]),
             ("gas_fraction_floor 1e-300", lambda s: s["coupling"].update(gas_fraction_floor=1e-300),
              ["coupling.gas_fraction_floor", "[0.01, 1)"])]
    for what, edit, words in cases:
        expect(what, runs.run(runs.case(edit)), 2, *words)


def undefined_script_variable(runs):
    def script(text):
        return text.replace("neigh_modify    delay 0",
                            "neigh_modify    delay 0\nvariable        spare equal ${no_such_value}*2")
    case = runs.case(script=script)
    line = next(n for n, l in enumerate(open(os.path.join(case, "column.in")), 1) if "no_such_value" in l)
    expect("undefined ${no_such_value}", runs.run(case), 2, "no_such_value", f"column.in line {line}")


def variable_used_before_its_definition(runs):
    """LIGGGHTS reads in order: a use above the definition aborts with "Substitution for illegal variable"
    (no name). Inside an `if`'s quoted branch, or in a script that jumps back to a label, it may be valid."""
    def early(text):
        return text.replace("neigh_modify    delay 0",
                            "neigh_modify    delay 0\nprint           \"later ${later}\"") + "variable later equal 3\n"
    case = runs.case(script=early)
    lines = [n for n, l in enumerate(open(os.path.join(case, "column.in")), 1) if "later" in l]
    expect("${later} above its definition", runs.run(case), 2, "uses the variable later before its definition",
           f"column.in line {lines[0]}", f"column.in line {lines[-1]}")

    def in_branch(text):
        return text.replace("neigh_modify    delay 0",
                            "neigh_modify    delay 0\nif \"0 > 1\" then \"print 'later ${later}'\"") + \
            "variable later equal 3\n"
    expect("${later} above its definition in an if branch that does not run", runs.run(runs.case(script=in_branch)),
           0, "done:")


def error_found_by_one_rank(runs):
    """LIGGGHTS' Error::one (here fix parcel refusing a sphere of the wrong diameter, on the rank that inserted
    it) ends in MPI_Abort: it used to exit with code 1 and no word from parcelflow."""
    def wrong_diameter(text):
        return text.replace("fix  parcels all parcel mode constant_np np ${np} scaling linear",
                            "fix  parcels all parcel mode constant_diameter diameter 0.05 dp 0.001")
    case = runs.case(script=wrong_diameter)
    for ranks in (1, 2):
        expect(f"a sphere refused by fix parcel, {ranks} rank(s)", runs.run(case, ranks=ranks), 2, "ERROR on proc",
               "'mode constant_diameter diameter' is 0.05",
               "liggghts.script = column.in stopped with the LIGGGHTS ERROR",
               "nparcels = '300'")


def infinite_parcel_velocity(runs):
    case = runs.case(script=lambda text: text + "set atom 7 vx 1e400\n")
    expect("parcel 7 with an infinite velocity", runs.run(case), None, "parcel 7 has a non-finite velocity", "inf",
           "DEM step")


if __name__ == "__main__":
    main([unwritable_output, case_yaml_is_a_folder, script_that_is_a_folder_or_empty, end_below_one_gas_step,
          values_the_solver_cannot_honour, undefined_script_variable, variable_used_before_its_definition,
          error_found_by_one_rank, infinite_parcel_velocity])
