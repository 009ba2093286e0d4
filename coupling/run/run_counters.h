// Everything a coupled run counts, in one place: clamps, floors, fallbacks and solver trouble are never
// silent (DESIGN section 4). Each rank counts its own cells and parcels; the gas solver's counts are the
// same on all ranks. The monitors and the checkpoint read the counters through perRank() and global(), so a
// new counter is added here once.
#pragma once

#include <mpi.h>

#include <utility>
#include <vector>

namespace parcelflow::coupling {

struct RunCounters {
  long floor_hits = 0;        // cell-steps whose a_g was raised to the floor
  long floor_spills = 0;      // cell-steps that gave solids above 1 - floor to their neighbours (excess_solids)
  long drag_floored = 0;      // parcel-steps whose drag was evaluated at the floor
  long drag_invalid = 0;      // parcel-steps with invalid drag input
  long drag_above_one = 0;    // parcel-steps that saw a_g above 1
  long drag_filter_clamped = 0;  // parcel-steps whose filtered-drag correction was bounded (drag_law.hpp)
  long orphans = 0;           // parcel-steps without a fluid cell in the stencil (no gas force)
  long fallbacks = 0;         // parcel-steps the centroid kernel put into a neighbouring fluid cell
  long pressure_iterations = 0, preconditioner_builds = 0, unconverged_solves = 0;  // same on all ranks
  double min_gas_fraction = 1.0;  // lowest a_g deposited so far

  // The per-rank counters (summed over ranks for a global value), by name.
  std::vector<std::pair<const char*, long*>> perRank() {
    return {{"floor_hits", &floor_hits}, {"floor_spills", &floor_spills}, {"drag_floored", &drag_floored},
            {"drag_invalid", &drag_invalid}, {"drag_above_one", &drag_above_one},
            {"drag_filter_clamped", &drag_filter_clamped}, {"orphans", &orphans}, {"kernel_fallbacks", &fallbacks}};
  }
  // The counters that are the same on every rank, by name.
  std::vector<std::pair<const char*, long*>> global() {
    return {{"pressure_iterations_total", &pressure_iterations},
            {"preconditioner_builds", &preconditioner_builds},
            {"unconverged_solves", &unconverged_solves}};
  }
  // A copy with every per-rank counter summed and the minimum taken over ranks. Collective.
  RunCounters totals(MPI_Comm comm) const {
    RunCounters t = *this;
    const auto fields = t.perRank();
    std::vector<long> local, sum(fields.size());
    for (const auto& field : fields) local.push_back(*field.second);
    MPI_Allreduce(local.data(), sum.data(), static_cast<int>(local.size()), MPI_LONG, MPI_SUM, comm);
    for (std::size_t k = 0; k < fields.size(); ++k) *fields[k].second = sum[k];
    MPI_Allreduce(&min_gas_fraction, &t.min_gas_fraction, 1, MPI_DOUBLE, MPI_MIN, comm);
    return t;
  }
};

}  // namespace parcelflow::coupling
