// The DEM side of a coupled run: everything that touches LIGGGHTS. Starts the in-process instance with the
// case's script (from the case folder, so its includes resolve), checks its time step against case.yaml,
// continues from a LIGGGHTS restart when asked, advances it, and writes its part of a checkpoint.
//
// Variables parcelflow passes to the script (a case may not set them in liggghts.variables):
//   dem_step      the DEM time step of case.yaml (`timestep ${dem_step}`);
//   restarting    0 for a fresh start, 1 when continuing a checkpoint;
//   restart_file  the LIGGGHTS restart to read when restarting (else "none");
//   geometry_stl  case.yaml's geometry as a closed STL file (geometry_stl.h), for `fix mesh/surface file
//                 ${geometry_stl}`: the parcels' walls the gas's (else "none").
// A restartable script reads ${restart_file} instead of creating the box and skips its filling and settling
// when ${restarting} is 1 (coupling/README.md, "Checkpoints").
#pragma once

#include <mpi.h>

#include <array>
#include <memory>
#include <string>

#include "coupling/run/coupling_settings.h"
#include "coupling/dem/dem_parcels.h"

namespace parcelflow::coupling {

class LiggghtsInstance;

class DemEngine {
 public:
  // Validates the settings (reserved variable names, undefined variables of the script) before LIGGGHTS
  // starts; throws cfd::ConfigError.
  DemEngine(MPI_Comm world, const CaseSettings& settings, const std::string& case_folder,
            const std::string& log_file);
  ~DemEngine();

  // Runs the script (a fresh start, or `restart_file` non-empty: continue from it; `geometry_stl` the path
  // the script's ${geometry_stl} gives), checks the time step
  // (against the script's and the contact time, contact_time_check.h), finds the parcel fixes, refuses a
  // script that inserted no parcel and runs `run 0` (neighbour lists built, forces at hand for the first chunk).
  void start(const std::string& restart_file = {}, const std::string& geometry_stl = {});

  DemParcels& parcels() { return *parcels_; }
  const DemParcels& parcels() const { return *parcels_; }
  long step() const;  // LIGGGHTS' time step counter
  // Whether the script's box is periodic along x, y, z (its `boundary` command).
  std::array<bool, 3> periodicAxes() const;

  void advance(int steps);  // `run steps pre no post no`, LIGGGHTS' per-chunk output filtered
  // LIGGGHTS write_restart of all parcels with their columns, the contact history and the forces the next
  // step starts from, then `run 0` (write_restart moves atoms between ranks): the run goes on exactly as a
  // run restarted from the file does. Collective.
  void writeRestart(const std::string& path);

 private:
  MPI_Comm world_;
  CaseSettings settings_;
  std::string case_folder_, log_file_;
  std::unique_ptr<LiggghtsInstance> lammps_;
  std::unique_ptr<DemParcels> parcels_;
};

}  // namespace parcelflow::coupling
