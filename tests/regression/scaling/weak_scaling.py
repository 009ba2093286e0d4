"""Weak scaling by counting, not timing: the fluidized column widened in x in proportion to the ranks
(P columns of 20 x 20 x 100 mm side by side, 1,146 parcels and 625 cells each, LIGGGHTS and METIS both split
along x) runs 100 coupling steps on 1, 2, 4 and 8 ranks (oversubscribed: nothing is timed). A PMPI library
(mpi_counter.c) counts, per rank, the point-to-point messages and bytes and the collective calls and bytes
during the coupled loop, the ranks it sends to, and the peak memory. Asserted, for the busiest rank per coupling
step from 4 to 8 ranks: at most 1.1 times the collective calls and 1.3 times their bytes (the coupler's
all-to-all-v carry only the cells next to a rank's parcels), and at most 15 % more peak memory (the known
exception that grows: the coupler's global fluid-cell map, 16 bytes per background cell on every rank,
coupling/exchange/cell_owner_map.h). Reported, not asserted: point-to-point messages and partners. They grow
with the ranks here because BoomerAMG's coarse levels of this tiny mesh (625 cells per rank) reach every rank;
with block_cholesky (no hypre) a rank sends to 3-6 others on 8 ranks (METIS' parts), but PCG then needs more
iterations per step the more blocks there are."""
import os
import re
import shutil
import subprocess
import sys
import tempfile

import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, fail, replace_in_file  # noqa: E402

STEPS = 100


def make_case(work, ranks):
    case = os.path.join(work, f"column_x{ranks}")
    shutil.copytree(os.path.join(CASES, "fluidized_column"), case, ignore=shutil.ignore_patterns("output"))
    width = 0.02 * ranks
    replace_in_file(os.path.join(case, "column.in"), [
        ("processors      * * 1", "processors      * 1 1"),
        ("box block 0 0.02 0 0.02", f"box block 0 {width} 0 0.02"),
        ("xplane 0.02", f"xplane {width}"),
        ("region          fill block ${fill_margin} ${fill_hi}",
         f"variable        fill_xhi equal {width}-${{fill_margin}}\n"
         "region          fill block ${fill_margin} ${fill_xhi}"),
        ("run             12000", "run             3000")])
    path = os.path.join(case, "case.yaml")
    s = yaml.safe_load(open(path))
    s["liggghts"]["variables"]["nparcels"] = str(1146 * ranks)
    s["mesh"]["lengths"][0] = width
    s["mesh"]["cells"][0] = 5 * ranks
    s["output"].update({"monitor_interval": 0.01, "progress_interval": 1e6})
    # BoomerAMG (the default): the column's block_cholesky is one exact block per rank, whose PCG iterations
    # grow with the number of blocks.
    s.pop("solver", None)
    yaml.safe_dump(s, open(path, "w"))
    return case, s["time"]["gas_step"]


def measure(parcelflow, mpiexec, flags, counter_lib, work, ranks):
    case, gas_step = make_case(work, ranks)
    counts = os.path.join(work, f"counts_{ranks}.txt")
    command = [mpiexec] + flags + ["-np", str(ranks), "-x", f"LD_PRELOAD={counter_lib}",
                                   "-x", f"MPI_COUNTER_FILE={counts}", parcelflow, "run", case,
                                   "--output", os.path.join(work, f"out_{ranks}"), "--end", repr(STEPS * gas_step)]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        fail(f"{' '.join(command)}: exit {done.returncode}\n{done.stdout[-2000:]}{done.stderr[-2000:]}")
    iterations = float(re.search(r"([0-9.]+) pressure iterations per step", done.stdout).group(1))
    rows = [list(map(int, line.split())) for line in open(counts)]
    if len(rows) != ranks:
        fail(f"{len(rows)} counter lines for {ranks} ranks")
    busiest = {name: max(r[k] for r in rows) / (STEPS if k < 5 else 1)
               for k, name in [(1, "messages"), (2, "bytes"), (3, "collectives"), (4, "collective_bytes"),
                               (5, "max_rss_kb"), (6, "partners")]}
    print(f"[measured] {ranks} rank(s), {1146 * ranks} parcels, {625 * ranks} cells; busiest rank per coupling step: "
          f"{busiest['messages']:.1f} messages, {busiest['bytes'] / 1e3:.1f} kB, {busiest['collectives']:.1f} "
          f"collectives ({busiest['collective_bytes'] / 1e3:.2f} kB); peak memory {busiest['max_rss_kb'] / 1e3:.1f} MB; "
          f"{iterations} pressure iterations per step; sends to {busiest['partners']:.0f} other ranks")
    return busiest


def main():
    parcelflow, mpiexec, counter_lib = sys.argv[1:4]
    flags = sys.argv[4:]
    work = tempfile.mkdtemp(prefix="pf_scaling_")
    try:
        result = {p: measure(parcelflow, mpiexec, flags, counter_lib, work, p) for p in (1, 2, 4, 8)}
    finally:
        shutil.rmtree(work, ignore_errors=True)
    four, eight = result[4], result[8]
    for name, factor in [("collectives", 1.1), ("collective_bytes", 1.3), ("max_rss_kb", 1.15)]:
        if eight[name] > factor * four[name]:
            fail(f"{name} per rank grows from 4 to 8 ranks: {four[name]:.1f} -> {eight[name]:.1f} "
                 f"(allowed x{factor})")
    print("PASS")


if __name__ == "__main__":
    main()
