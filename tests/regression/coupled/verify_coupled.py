#!/usr/bin/env python3
"""Verification of the coupled solver against independently computed values (issue 4).

  terminal NP   one parcel (np = NP, real diameter 100 um) settling in still air must reach the Wen-Yu
                terminal velocity, solved here by bisection, within 1 %.
  smoothed      the fluidized_column bed with coupling.kernel.smoothing_length one cell (4 mm) and without:
                the solids volume of the gas-fraction field (sum (1 - a_g) V) must equal the parcels' volume
                (sum np pi/6 dp^3) to 1e-9 with smoothing (conservative, no flux through the walls), and the
                cell-to-cell scatter of a_g in the bed must fall (rms of the differences of neighbours in x).
  spilled       the fluidized_column bed with a gas-fraction floor of 0.38 (some of the packed bed's cells hold
                more solids than 0.62), with coupling.excess_solids spill (the default) and discard: spilled, the field's
                solids volume must equal the parcels' to 1e-9 with no cell above 0.62; discarded, it must be
                short by more than 1e-3. (A floor of 0.42, below the bed's mean packing, leaves 1.4 % for the
                floor after the 20 passes.)
  packed        the fluidized_column bed at 0.3 m/s (below minimum fluidization) with the Ergun drag law:
                the pressure drop between the cell layers at 6 and 14 mm must equal, within 3 %, the
                Ergun pressure drop for the bed's measured voidage. The voidage is read per cell from the
                HDF5 fields; the side walls loosen the packing (gas fraction 0.52 in the corner columns,
                0.38 in the centre), so the prediction lets each cell column carry the flow that gives the
                same pressure drop (parallel channels). The Ergun value at the layer-mean voidage is
                printed too.

usage: verify_coupled.py PARCELFLOW MPIEXEC... -- CHECK [ARG]
"""
import csv
import math
import os
import sys

import h5py

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from parcelflow_runs import CASES, run_case  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
RHO_P, RHO_G, MU, G = 2500.0, 1.2, 1.8e-5, 9.81


def wen_yu_terminal_velocity(dp):
    """Still air, a_g -> 1: (rho_p - rho_g) V g = pi/8 d^2 C_D rho_g v^2, C_D = 24/Re (1 + 0.15 Re^0.687)."""
    weight = (RHO_P - RHO_G) * math.pi / 6 * dp**3 * G
    lo, hi = 1e-9, 100.0
    for _ in range(200):
        v = 0.5 * (lo + hi)
        re = RHO_G * v * dp / MU
        cd = 24 / re * (1 + 0.15 * re**0.687) if re < 1000 else 0.44
        lo, hi = (v, hi) if math.pi / 8 * dp * dp * cd * RHO_G * v * v < weight else (lo, v)
    return lo


def check_terminal(parcelflow, launcher, np_):
    dp = 1e-4
    def edit(s):
        s["liggghts"]["variables"].update({"np": str(np_), "diameter": repr(dp * np_ ** (1 / 3))})
    out = run_case(parcelflow, launcher, os.path.join(HERE, "single_parcel"), edit)
    rows = [(float(r["time"]), float(r["mean_z_type1"])) for r in csv.DictReader(open(os.path.join(out, "monitors.csv")))]
    late = [(t, z) for t, z in rows if t >= 0.3]  # after more than 5 response times
    mt = sum(t for t, _ in late) / len(late)
    mz = sum(z for _, z in late) / len(late)
    v = -sum((t - mt) * (z - mz) for t, z in late) / sum((t - mt) ** 2 for t, _ in late)
    expected = wen_yu_terminal_velocity(dp)
    error = v / expected - 1
    print(f"[measured] terminal velocity, np = {np_}: {v:.6f} m/s, Wen-Yu {expected:.6f} m/s, error {100 * error:+.3f} %")
    return abs(error) < 0.01


def ergun_gradient(eps, u, dp=1e-3):
    return 150 * MU * u * (1 - eps) ** 2 / (eps**3 * dp * dp) + 1.75 * RHO_G * u * u * (1 - eps) / (eps**3 * dp)


def bisect(f, lo, hi, target):
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) < target else (lo, mid)
    return 0.5 * (lo + hi)


def check_packed(parcelflow, launcher):
    u = 0.3
    def edit(s):
        s["time"]["end"] = 0.06
        s["coupling"]["drag"] = "Ergun"
        s["boundaries"]["zmin"]["superficial_velocity"] = [0, 0, u]
        s["monitors"]["pressure_planes"] = [0.006, 0.014, 0.05]
    out = run_case(parcelflow, launcher, os.path.join(CASES, "fluidized_column"), edit)
    last = list(csv.DictReader(open(os.path.join(out, "monitors.csv"))))[-1]
    dz = 0.004
    measured = float(last["p_z0.006"]) - float(last["p_z0.014"]) - RHO_G * G * 2 * dz
    fields = h5py.File(os.path.join(out, "fields_000000.h5"))
    ids = h5py.File(os.path.join(out, "fields_mesh.h5"))["global_id"][:]
    eps = fields["gas_fraction"][:]
    nx, ny = 5, 5
    # layers 1, 2, 3 (centres 6, 10, 14 mm): the drop between the outer centres spans half of 1 and 3
    weight = {1: 0.5, 2: 1.0, 3: 0.5}
    columns = {}
    for gid, e in zip(ids, eps):
        k = gid // (nx * ny)
        if k in weight:
            columns.setdefault(gid % (nx * ny), []).append((weight[k], e))
    def column_drop(col, uc):
        return sum(w * dz * ergun_gradient(e, uc) for w, e in col)
    def mean_flow(drop):
        return sum(bisect(lambda uc: column_drop(col, uc), 0.0, 50.0, drop) for col in columns.values()) / len(columns)
    predicted = bisect(mean_flow, 0.0, 1e5, u)
    layer_mean = sum(w * e for col in columns.values() for w, e in col) / sum(w for col in columns.values() for w, _ in col)
    uniform = 2 * dz * ergun_gradient(layer_mean, u)
    error = measured / predicted - 1
    print(f"[measured] packed bed at {u} m/s: pressure drop {measured:.3f} Pa; Ergun with each cell column's "
          f"voidage {predicted:.3f} Pa (error {100 * error:+.2f} %); Ergun at the mean voidage {layer_mean:.4f}: "
          f"{uniform:.3f} Pa (ratio {measured / uniform:.3f}, wall channelling)")
    return abs(error) < 0.03


def solids_of_the_bed(parcelflow, launcher, setting, floor=None):
    """bed_fields(on): the fluidized column run for 2 gas steps, with setting(coupling section) applied when on:
    the field's solids volume, the parcels' volume, the rms a_g difference of x-neighbours in the bed, the
    lowest a_g."""
    def bed_fields(on):
        def edit(s):
            s["time"]["end"] = 0.004
            s["output"]["fields_interval"] = 0.002
            s["output"]["parcels_interval"] = 0.002
            if floor is not None:
                s["coupling"]["gas_fraction_floor"] = floor
            if on:
                setting(s["coupling"])
        out = run_case(parcelflow, launcher, os.path.join(CASES, "fluidized_column"), edit)
        field = h5py.File(os.path.join(out, "fields_000001.h5"))
        mesh = h5py.File(os.path.join(out, "fields_mesh.h5"))
        parcels = h5py.File(os.path.join(out, "parcels_000001.h5"))
        ids, a = mesh["global_id"][:], field["gas_fraction"][:].ravel()
        cell_volume = 0.004 ** 3
        solids = float(((1 - a) * cell_volume).sum())
        dp, np_ = parcels["dp"][:].ravel(), parcels["np"][:].ravel()
        parcel_volume = float((np_ * math.pi / 6 * dp ** 3).sum())
        grid = {int(g): e for g, e in zip(ids, a)}
        # neighbours in x in the lowest 3 layers (the packed bed), 5 x 5 x 25 cells
        diffs = [grid[g] - grid[g + 1] for g in grid if g // 25 < 3 and g % 5 < 4]
        return solids, parcel_volume, math.sqrt(sum(d * d for d in diffs) / len(diffs)), float(a.min())
    return bed_fields


def check_smoothed(parcelflow, launcher):
    bed_fields = solids_of_the_bed(parcelflow, launcher, lambda c: c["kernel"].update(smoothing_length=0.004))
    plain, volume, scatter, _ = bed_fields(False)
    smoothed, volume_s, scatter_s, _ = bed_fields(True)
    error = smoothed / volume_s - 1
    print(f"[measured] solids volume of the field / parcels' volume - 1: smoothed {error:.2e}, unsmoothed "
          f"{plain / volume - 1:.2e}; rms a_g difference of x-neighbours in the bed: {scatter:.4f} unsmoothed, "
          f"{scatter_s:.4f} smoothed over 4 mm")
    return abs(error) < 1e-9 and scatter_s < 0.5 * scatter


def check_spilled(parcelflow, launcher):
    # spill is the default: "on" sets discard, so that the default's own value is what is checked
    bed_fields = solids_of_the_bed(parcelflow, launcher, lambda c: c.update(excess_solids="discard"), floor=0.38)
    spilled, volume_s, _, lowest = bed_fields(False)
    cut, volume, _, _ = bed_fields(True)
    error = spilled / volume_s - 1
    print(f"[measured] solids volume of the field / parcels' volume - 1 with a floor of 0.38: spilled {error:.2e}, "
          f"discarded {cut / volume - 1:.2e}; lowest a_g spilled {lowest:.6f}")
    return abs(error) < 1e-9 and cut / volume - 1 < -1e-3 and lowest >= 0.38 - 1e-12


def main():
    sep = sys.argv.index("--")
    parcelflow, launcher = sys.argv[1], sys.argv[2:sep]
    check, args = sys.argv[sep + 1], sys.argv[sep + 2:]
    checks = {"terminal": lambda: check_terminal(parcelflow, launcher, int(args[0])),
              "packed": lambda: check_packed(parcelflow, launcher),
              "smoothed": lambda: check_smoothed(parcelflow, launcher),
              "spilled": lambda: check_spilled(parcelflow, launcher)}
    ok = checks[check]()
    print(f"{1 if ok else 0} passed, {0 if ok else 1} failed")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
