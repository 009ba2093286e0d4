// Warnings printed on the terminal at the step where a problem starts, not only in the closing summary:
// coarse-grained parcels against the mesh and the bed (parcel_size_report.h), parcels whose centre is in
// no fluid cell and parcels whose centre lies outside case.yaml's geometry (the LIGGGHTS walls and the gas's
// disagree; both at the first coupling step), parcels lost (at the first step
// after the DEM advance that lost them), pressure or momentum solves stopped at max_iterations (the first,
// then every kUnconvergedEvery-th such step) and a pressure solve that did no iteration (its stopping rule was
// met by the starting residual). The coupled loop calls afterGasStep() once per step, on all ranks,
// before the blow-up guard, so that a warning about the cause comes before the guard's stop.
#pragma once

#include <mpi.h>

#include <string>

#include "cfd/solver/gas_solver.hpp"
#include "coupling/exchange/cell_owner_map.h"
#include "coupling/run/parcel_mesh_coupler.h"
#include "coupling/run/parcel_size_report.h"
#include "coupling/run/run_counters.h"

namespace parcelflow::coupling {

class RunWarnings {
 public:
  static constexpr long kUnconvergedEvery = 100;

  // `geometry`: case.yaml's (nullptr when it has none: the whole box is fluid).
  RunWarnings(MPI_Comm comm, const cfd::Mesh& mesh, const CellOwnerMap& owners, long parcels,
              std::string pressure_stop_rule, KernelReach kernel_reach, const cfd::Geometry* geometry);

  // `batch`: the parcels at the start of the step (their ids in `ids`); time and step at its end. Collective.
  void afterGasStep(const ParcelBatch& batch, const std::vector<long>& ids, const cfd::StepReport& report,
                 long parcels, double time, long step);

 private:
  void checkOutsideMesh(const ParcelBatch& batch, const std::vector<long>& ids, long parcels);
  // The first parcel (by rank) that `outside` selects: how many there are over all ranks, and its id and position.
  template <class Outside>
  long countOutside(const ParcelBatch& batch, const std::vector<long>& ids, const Outside& outside,
                    double (&example)[4]) const;
  void reportParcelSizes(const ParcelBatch& batch);

  MPI_Comm comm_;
  int rank_ = 0;
  const cfd::Mesh& mesh_;
  const CellOwnerMap& owners_;
  long parcels_;
  std::string pressure_stop_rule_;  // what "converged" meant, for the warning of a solve without iterations
  KernelReach kernel_reach_;
  const cfd::Geometry* geometry_;
  bool first_ = true, warned_no_iterations_ = false;
  long unconverged_steps_ = 0;
};

}  // namespace parcelflow::coupling
