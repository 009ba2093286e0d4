#include "coupling/run/run_warnings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

namespace parcelflow::coupling {

RunWarnings::RunWarnings(MPI_Comm comm, const cfd::Mesh& mesh, const CellOwnerMap& owners, long parcels,
                         std::string pressure_stop_rule, KernelReach kernel_reach, const cfd::Geometry* geometry)
    : comm_(comm),
      mesh_(mesh),
      owners_(owners),
      parcels_(parcels),
      pressure_stop_rule_(std::move(pressure_stop_rule)),
      kernel_reach_(kernel_reach),
      geometry_(geometry) {
  MPI_Comm_rank(comm, &rank_);
}

template <class Outside>
long RunWarnings::countOutside(const ParcelBatch& batch, const std::vector<long>& ids, const Outside& outside,
                               double (&example)[4]) const {
  long count = 0;
  for (std::size_t p = 0; p < batch.size; ++p) {
    if (!outside(batch.x + 3 * p) || count++ > 0) continue;
    example[0] = static_cast<double>(ids[p]);
    for (int d = 0; d < 3; ++d) example[1 + d] = batch.x[3 * p + d];
  }
  long total = 0;
  MPI_Allreduce(&count, &total, 1, MPI_LONG, MPI_SUM, comm_);
  if (total == 0) return 0;
  struct { int has; int rank; } mine{count > 0 ? 1 : 0, rank_}, first{};
  MPI_Allreduce(&mine, &first, 1, MPI_2INT, MPI_MAXLOC, comm_);
  MPI_Bcast(example, 4, MPI_DOUBLE, first.rank, comm_);
  return total;
}

void RunWarnings::checkOutsideMesh(const ParcelBatch& batch, const std::vector<long>& ids, long parcels) {
  const cfd::CartesianBackground& bg = mesh_.background();
  const auto inNoFluidCell = [&](const double* x) {
    int ijk[3];
    for (int d = 0; d < 3; ++d) ijk[d] = static_cast<int>(std::floor((x[d] - bg.origin()[d]) / bg.spacing()[d]));
    return !(bg.inside(ijk[0], ijk[1], ijk[2]) && owners_.ownerRank(bg.index(ijk[0], ijk[1], ijk[2])) >= 0);
  };
  double example[4] = {0.0, 0.0, 0.0, 0.0};  // id, x, y, z of the first one
  const long outside = countOutside(batch, ids, inNoFluidCell, example);
  if (outside > 0 && rank_ == 0)
    std::printf("parcelflow: warning: %s%ld of %ld parcels have their centre in no fluid cell of the gas mesh at "
                "the first coupling step (e.g. parcel %.0f at (%g, %g, %g)); they feel the gas only through the fluid "
                "cells their kernel reaches, and none if it reaches none (column `orphans` of monitors.csv); compare "
                "the LIGGGHTS regions with mesh.origin, mesh.lengths and geometry\n",
                outside == parcels ? "all: " : "", outside, parcels, example[0], example[1], example[2], example[3]);
  if (geometry_ == nullptr) return;
  // In a fluid cell but outside the geometry: on cut cells the gas's wall is the geometry's, so the parcel is
  // beyond the gas's wall; on a staircase the cell's centre is inside but the wall LIGGGHTS keeps the parcels in
  // should be the geometry's too.
  const auto beyondTheGeometry = [&](const double* x) {
    return !inNoFluidCell(x) && !geometry_->isFluid(cfd::Vec3(x[0], x[1], x[2]));
  };
  const long beyond = countOutside(batch, ids, beyondTheGeometry, example);
  if (beyond > 0 && rank_ == 0)
    std::printf("parcelflow: warning: %ld of %ld parcels have their centre outside case.yaml's geometry at the first "
                "coupling step (e.g. parcel %.0f at (%g, %g, %g)): the walls LIGGGHTS keeps them in and the gas's "
                "walls (geometry) disagree; make the LIGGGHTS walls the geometry's surfaces\n",
                beyond, parcels, example[0], example[1], example[2], example[3]);
}

void RunWarnings::reportParcelSizes(const ParcelBatch& batch) {
  // D, np, D - dp, dp and -dp (the smallest dp), all reduced by one maximum
  double largest[5] = {0.0, 0.0, 0.0, 0.0, -std::numeric_limits<double>::max()};
  for (std::size_t p = 0; p < batch.size; ++p) {
    const double D = batch.dp[p] * std::cbrt(batch.np[p]);
    largest[0] = std::max(largest[0], D);
    largest[1] = std::max(largest[1], batch.np[p]);
    largest[2] = std::max(largest[2], D - batch.dp[p]);
    largest[3] = std::max(largest[3], batch.dp[p]);
    largest[4] = std::max(largest[4], -batch.dp[p]);
  }
  MPI_Allreduce(MPI_IN_PLACE, largest, 5, MPI_DOUBLE, MPI_MAX, comm_);
  if (rank_ != 0) return;
  const ParcelSizes sizes{largest[0], largest[1], largest[2], -largest[4], largest[3]};
  for (const std::string& line : parcelSizeReport(sizes, kernel_reach_))
    std::printf("%s\n", line.c_str());
}

void RunWarnings::afterGasStep(const ParcelBatch& batch, const std::vector<long>& ids,
                               const cfd::StepReport& report, long parcels, double time, long step) {
  if (first_) {
    reportParcelSizes(batch);
    checkOutsideMesh(batch, ids, parcels_);
  }
  first_ = false;
  if (parcels < parcels_ && rank_ == 0)
    std::printf("parcelflow: warning: t = %g s (step %ld): %ld parcels lost in the last DEM advance, %ld left%s\n",
                time, step,
                parcels_ - parcels, parcels, parcels == 0 ? ": every parcel is lost" : "");
  parcels_ = parcels;
  if (report.unconvergedSolves > 0 && unconverged_steps_++ % kUnconvergedEvery == 0 && rank_ == 0)
    std::printf("parcelflow: warning: t = %g s (step %ld): %d linear solves stopped at max_iterations without "
                "converging (%ld steps with such solves so far; see solver.pressure / solver.momentum in "
                "cfd/README.md)\n",
                time, step, report.unconvergedSolves, unconverged_steps_);
  if (report.pressureIterations == 0 && !warned_no_iterations_) {
    warned_no_iterations_ = true;
    if (rank_ == 0)
      std::printf("parcelflow: warning: t = %g s (step %ld): the pressure solve did no iteration: its residual was "
                  "already below %s\n",
                  time, step, pressure_stop_rule_.c_str());
  }
}

}  // namespace parcelflow::coupling
