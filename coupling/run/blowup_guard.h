// Stops a coupled run whose state diverged, before that step's outputs and checkpoint are written (so the
// last checkpoint on disk is the last good state; coupling/README.md, "Blow-up guards"): a non-finite gas
// pressure or velocity, a gas Courant number or continuity error above coupling.guards' limits, or a sudden
// loss of parcels. The message names the quantity and its limit, where (cell centre) and when (time, gas
// step), and the last checkpoint.
#pragma once

#include <mpi.h>

#include <stdexcept>
#include <string>

#include "cfd/solver/gas_solver.hpp"
#include "coupling/run/coupling_settings.h"

namespace parcelflow::coupling {

// Thrown on every rank alike; `parcelflow` reports it once and exits with code 3.
class DivergedError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class BlowupGuard {
 public:
  BlowupGuard(MPI_Comm comm, const GuardSettings& limits, long parcels);

  // Right after the gas step, before its values reach the parcels (non-finite gas values would crash
  // LIGGGHTS), and after the DEM advance (`gas` null: the parcel count only). Throws DivergedError when the
  // state diverged; `time` and `step` are those at the end of the step. Collective (one small all-reduce).
  void check(const cfd::GasSolver* gas, const cfd::StepReport& report, long parcels, double time, long step,
             const std::string& last_checkpoint);

 private:
  std::string nonFiniteCell(const cfd::GasSolver& gas) const;  // "" or what and where, on every rank
  std::string fastestCell(const cfd::GasSolver& gas) const;    // the largest |u| and its cell centre
  // With mesh.walls cut_cells, where to read about the known defect of films left by a wall a hair off a cell face
  // ("" otherwise)
  std::string cutCellHint(const cfd::GasSolver& gas) const;

  MPI_Comm comm_;
  int rank_ = 0;
  GuardSettings limits_;
  long initial_parcels_, parcels_;
};

}  // namespace parcelflow::coupling
