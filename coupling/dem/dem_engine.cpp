#include "coupling/dem/dem_engine.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cfd/base/config_error.hpp"
#include "cfd/base/number_text.hpp"
#include "coupling/dem/contact_time_check.h"
#include "domain.h"
#include "lammps.h"
#include "coupling/dem/liggghts_instance.h"
#include "coupling/dem/script_error_report.h"
#include "coupling/dem/script_variables.h"
#include "update.h"

namespace parcelflow::coupling {

using cfd::exactNumber;

namespace {

const char* const kReservedVariables[] = {"dem_step", "restarting", "restart_file", "geometry_stl"};

}  // namespace

DemEngine::DemEngine(MPI_Comm world, const CaseSettings& settings, const std::string& case_folder,
                     const std::string& log_file)
    : world_(world), settings_(settings), case_folder_(case_folder), log_file_(log_file) {
  for (const auto& [name, value] : settings.liggghts.variables)
    for (const char* reserved : kReservedVariables)
      if (name == reserved)
        throw cfd::ConfigError("liggghts.variables." + name, value,
                               std::string("a name other than dem_step, restarting, restart_file and geometry_stl: parcelflow sets ") +
                                   reserved + " itself");
  std::vector<std::string> passed(std::begin(kReservedVariables), std::end(kReservedVariables));
  for (const auto& variable : settings.liggghts.variables) passed.push_back(variable.first);
  checkScriptVariables(case_folder, settings.liggghts.script, passed, settings.liggghts.variables);
}

DemEngine::~DemEngine() = default;

void DemEngine::start(const std::string& restart_file, const std::string& geometry_stl) {
  const TimeSettings& time = settings_.time;
  const std::string restart =
      restart_file.empty() ? std::string("none") : std::filesystem::absolute(restart_file).string();
  std::vector<std::string> args = {"-log", log_file_, "-var", "dem_step", exactNumber(time.dem_step),
                                   "-var", "restarting", restart_file.empty() ? "0" : "1",
                                   "-var", "restart_file", restart,
                                   "-var", "geometry_stl", geometry_stl.empty() ? std::string("none") : geometry_stl};
  for (const auto& [name, value] : settings_.liggghts.variables) args.insert(args.end(), {"-var", name, value});
  // LIGGGHTS runs the case's script from the case folder, so that its includes and data files resolve.
  if (chdir(case_folder_.c_str()) != 0)
    throw cfd::ConfigError("cannot enter the case folder '" + case_folder_ + "'");
  lammps_ = std::make_unique<LiggghtsInstance>(world_, args);
  int rank = 0;
  MPI_Comm_rank(world_, &rank);
  std::string passed = "liggghts.variables:";
  for (const auto& [name, value] : settings_.liggghts.variables) passed += " " + name + " = '" + value + "'";
  if (settings_.liggghts.variables.empty()) passed += " none";
  {
    const ScriptErrorReport report("parcelflow: error in case '" + case_folder_ + "': liggghts.script = " +
                                       settings_.liggghts.script +
                                       " stopped with the LIGGGHTS ERROR above, before the coupled run; " + passed +
                                       "\n",
                                   rank);
    try {
      lammps_->runFile(settings_.liggghts.script);
    } catch (const cfd::ConfigError& e) {  // found in one of the script's runs: it may come from a variable
      throw cfd::ConfigError(std::string(e.what()) + " (in liggghts.script = " + settings_.liggghts.script + "; " +
                             passed + ")");
    }
  }
  const double script_dt = lammps_->lammps()->update->dt;
  if (std::abs(script_dt - time.dem_step) > 1e-12 * time.dem_step)
    throw cfd::ConfigError("time.dem_step is " + exactNumber(time.dem_step) +
                           " s but the LIGGGHTS script sets timestep " + exactNumber(script_dt) +
                           " s; use `timestep ${dem_step}` in the script");
  parcels_ = std::make_unique<DemParcels>(lammps_->lammps());
  if (parcels_->globalCount() == 0)
    throw cfd::ConfigError("liggghts.script", settings_.liggghts.script,
                           "a script that inserts at least one parcel (LIGGGHTS has none when it ends)");
  const std::string contact = checkContactTime(lammps_->lammps(), time.dem_step);
  if (rank == 0 && !contact.empty())
    std::printf("parcelflow: DEM step %g s; %s (allowed: at least %.0f)\n", time.dem_step, contact.c_str(),
                kStepsPerContact);
  lammps_->quietCommand("run 0 post no");
}

long DemEngine::step() const { return static_cast<long>(lammps_->lammps()->update->ntimestep); }

std::array<bool, 3> DemEngine::periodicAxes() const {
  const int* periodic = lammps_->lammps()->domain->periodicity;
  return {periodic[0] != 0, periodic[1] != 0, periodic[2] != 0};
}

void DemEngine::advance(int steps) { lammps_->quietCommand("run " + std::to_string(steps) + " pre no post no"); }

void DemEngine::writeRestart(const std::string& path) {
  parcels_->keepForcesForRestart();
  lammps_->quietCommand("write_restart " + path);
  // write_restart moved atoms between ranks and rebuilt the ghosts, so the neighbour lists are stale: set up
  // again, exactly as a run restarted from this file does (the kept forces are put back in both).
  lammps_->quietCommand("run 0 post no");
}

}  // namespace parcelflow::coupling
