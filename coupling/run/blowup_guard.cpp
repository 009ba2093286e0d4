#include "coupling/run/blowup_guard.h"

#include <cmath>
#include <cstdio>

#include "coupling/run/broadcast_text.h"
#include "cfd/base/number_text.hpp"

namespace parcelflow::coupling {

namespace {

using cfd::formatNumbers;

std::string at(const cfd::Mesh& mesh, int cell) {
  const cfd::Vec3& x = mesh.cellCentre(cell);
  return formatNumbers(" at cell centre (%g, %g, %g)", x[0], x[1], x[2]);
}

}  // namespace

BlowupGuard::BlowupGuard(MPI_Comm comm, const GuardSettings& limits, long parcels)
    : comm_(comm), limits_(limits), initial_parcels_(parcels), parcels_(parcels) {
  MPI_Comm_rank(comm, &rank_);
}

std::string BlowupGuard::nonFiniteCell(const cfd::GasSolver& gas) const {
  const cfd::Mesh& mesh = gas.mesh();
  std::string found;
  for (int c = 0; c < mesh.nOwnedCells() && found.empty(); ++c) {
    const cfd::Vec3& u = gas.velocity()[c];
    if (!std::isfinite(gas.pressure()[c])) found = formatNumbers("pressure = %g", gas.pressure()[c]) + at(mesh, c);
    else if (!u.allFinite()) found = formatNumbers("gas velocity = (%g, %g, %g)", u[0], u[1], u[2]) + at(mesh, c);
  }
  struct { int has; int rank; } mine{found.empty() ? 0 : 1, rank_}, first{};
  MPI_Allreduce(&mine, &first, 1, MPI_2INT, MPI_MAXLOC, comm_);
  return first.has ? broadcastText(found, first.rank, comm_) : std::string();
}

std::string BlowupGuard::fastestCell(const cfd::GasSolver& gas) const {
  const cfd::Mesh& mesh = gas.mesh();
  struct { double speed; int rank; } mine{-1.0, rank_}, top{};
  int cell = 0;
  for (int c = 0; c < mesh.nOwnedCells(); ++c)
    if (gas.velocity()[c].norm() > mine.speed) {
      mine.speed = gas.velocity()[c].norm();
      cell = c;
    }
  MPI_Allreduce(&mine, &top, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm_);
  const std::string where = rank_ == top.rank ? at(mesh, cell) : std::string();
  return formatNumbers("largest gas speed %g m/s", top.speed) + broadcastText(where, top.rank, comm_);
}

std::string BlowupGuard::cutCellHint(const cfd::GasSolver& gas) const {
  if (gas.settings().mesh.walls != cfd::WallRepresentation::CutCells) return std::string();
  return "; on cut cells: a geometry plane a hair off a cell face leaves films of fluid across the faces beyond it, "
         "which carried spurious gas speeds in the full FCC case (cfd/README.md, \"Known defect: a wall a hair off a "
         "cell face\"; warned at the start of the run)";
}

void BlowupGuard::check(const cfd::GasSolver* gas, const cfd::StepReport& report, long parcels, double time,
                        long step, const std::string& last_checkpoint) {
  std::string what = gas ? nonFiniteCell(*gas) : std::string();
  if (!what.empty()) {
    what = "non-finite " + what;
  } else if (gas && !(report.cfl <= limits_.max_cfl)) {
    what = formatNumbers("gas Courant number %g above coupling.guards.max_cfl = %g; ", report.cfl, limits_.max_cfl) +
           fastestCell(*gas) + cutCellHint(*gas);
  } else if (gas && !(report.continuityError <= limits_.max_continuity_error)) {
    what = formatNumbers("continuity error %g above coupling.guards.max_continuity_error = %g",
                         report.continuityError, limits_.max_continuity_error);
  } else if (parcels_ - parcels > limits_.max_parcel_loss * initial_parcels_) {
    what = formatNumbers("%.0f of %.0f parcels lost in one coupling step, more than "
                         "coupling.guards.max_parcel_loss = %g of the %.0f the run started with",
                         static_cast<double>(parcels_ - parcels), static_cast<double>(parcels_),
                         limits_.max_parcel_loss, static_cast<double>(initial_parcels_));
  }
  parcels_ = parcels;
  if (what.empty()) return;
  throw DivergedError("the run diverged at t = " + formatNumbers("%g", time) + " s (gas step " + std::to_string(step) +
                      "): " + what + "; " +
                      (last_checkpoint.empty()
                           ? std::string("no checkpoint was written before (output.checkpoint_interval)")
                           : "the last good checkpoint is " + last_checkpoint));
}

}  // namespace parcelflow::coupling
