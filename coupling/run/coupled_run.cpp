#include "coupled_run.h"

#include <mpi.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>

#include "atom.h"
#include "cfd/config_error.hpp"
#include "cfd/field_writer.hpp"
#include "cfd/gas_solver.hpp"
#include "csv_writer.h"
#include "dem_parcels.h"
#include "lammps.h"
#include "liggghts_instance.h"
#include "parcel_mesh_coupler.h"
#include "plane_averages.h"
#include "progress_line.h"
#include "update.h"

namespace parcelflow::coupling {

namespace fs = std::filesystem;

struct CoupledRun::State {
  RunOptions options;
  CaseDefinition case_def;
  int rank = 0;
  fs::path output;

  std::unique_ptr<cfd::GasSolver> gas;
  std::unique_ptr<CellOwnerMap> owners;
  std::unique_ptr<ParcelMeshCoupler> coupler;
  std::unique_ptr<LiggghtsInstance> dem;
  std::unique_ptr<DemParcels> parcels;
  std::unique_ptr<PlaneAverages> planes;
  std::unique_ptr<CsvWriter> monitors;
  std::unique_ptr<cfd::FieldWriter> fields;

  int dem_steps = 1;
  long step = 0;
  double time = 0.0;
  double next_monitor = 0.0;
  double next_fields = 0.0;
  long initial_parcels = 0;
  // Counted, never silent: cells whose a_g was raised to the floor (cell-steps), parcels with no fluid
  // cell in their stencil (parcel-steps), parcels whose drag was evaluated at the floor (parcel-steps).
  long floor_hits = 0, orphans = 0, drag_floored = 0, drag_invalid = 0, drag_above_one = 0;
  long pressure_iterations = 0, preconditioner_builds = 0, unconverged_solves = 0;  // same on all ranks
  double min_gas_fraction_seen = 1.0;

  double wall_start = 0.0, next_progress = 0.0;
  ProgressState progress;

  SolidsOnCells solids;
  GasAtParcels at_parcels;
  std::vector<double> gas_fraction, velocity, grad_p;
};

namespace {

long sumLong(long local, MPI_Comm comm) {
  long global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_LONG, MPI_SUM, comm);
  return global;
}

std::vector<double> interleavedOwned(const cfd::VectorField& field, int n_owned) {
  std::vector<double> out(3 * static_cast<std::size_t>(n_owned));
  for (int c = 0; c < n_owned; ++c)
    for (int d = 0; d < 3; ++d) out[3 * c + d] = field[c][d];
  return out;
}

cfd::VectorField vectorField(const std::vector<double>& interleaved) {
  cfd::VectorField out(interleaved.size() / 3);
  for (std::size_t c = 0; c < out.size(); ++c) out[c] = cfd::Vec3(interleaved[3 * c], interleaved[3 * c + 1], interleaved[3 * c + 2]);
  return out;
}

// A height as a column label: shortest exact decimal form (0.05, not 0.050000000000000003).
std::string label(double v) {
  char buf[64];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

std::string number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

// Gas fraction, gas velocity, pressure and the solids velocity u_s = sum(w kappa v) / sum(w kappa)
// (zero where no parcel drags) of the owned cells, as one HDF5 snapshot.
void writeFields(CoupledRun::State& s);

CoupledRun::CoupledRun(const RunOptions& options) : s_(std::make_unique<State>()) { s_->options = options; }

CoupledRun::~CoupledRun() = default;

void CoupledRun::initialize() {
  State& s = *s_;
  MPI_Comm_rank(MPI_COMM_WORLD, &s.rank);
  // Everything parcelflow reads is checked before any work starts.
  s.case_def = readCase(s.options.case_folder);
  if (s.options.end_time > 0.0) s.case_def.settings.time.end = s.options.end_time;
  const CaseSettings& cs = s.case_def.settings;
  s.output = fs::absolute(s.options.output_folder.empty() ? fs::path(s.options.case_folder) / cs.output.folder
                                                          : fs::path(s.options.output_folder));
  if (s.rank == 0) fs::create_directories(s.output);
  MPI_Barrier(MPI_COMM_WORLD);

  s.gas = std::make_unique<cfd::GasSolver>(s.case_def.gas, MPI_COMM_WORLD);
  const cfd::Mesh& mesh = s.gas->mesh();
  std::vector<long> owned(mesh.nOwnedCells());
  for (int c = 0; c < mesh.nOwnedCells(); ++c) owned[c] = mesh.backgroundIndex(c);
  s.owners = std::make_unique<CellOwnerMap>(MPI_COMM_WORLD, mesh.background().size(), owned);
  BackgroundGrid grid;
  for (int d = 0; d < 3; ++d) {
    grid.origin[d] = mesh.background().origin()[d];
    grid.spacing[d] = mesh.background().spacing()[d];
    grid.cells[d] = mesh.background().n()[d];
  }
  TransferKernelOptions kernel_options;
  kernel_options.gaussianSharpness = cs.coupling.kernel.width;
  kernel_options.gaussianRadius = cs.coupling.kernel.radius;
  s.coupler = std::make_unique<ParcelMeshCoupler>(
      grid, *s.owners, makeTransferKernel(cs.coupling.kernel.type, kernel_options), makeDragLaw(cs.coupling.drag),
      DragLimits{cs.coupling.gas_fraction_floor},
      GasProperties{s.case_def.gas.gas.density, s.case_def.gas.gas.viscosity});
  std::vector<double> heights = cs.monitors.pressure_planes;
  if (cs.monitors.has_bed_pressure_drop)
    heights.insert(heights.end(), cs.monitors.bed_pressure_drop.begin(), cs.monitors.bed_pressure_drop.end());
  s.planes = std::make_unique<PlaneAverages>(mesh, heights, "monitors");

  // LIGGGHTS runs the case's script from the case folder, so that its includes and data files resolve.
  std::vector<std::string> args = {"-log", (s.output / "log.liggghts").string(), "-var", "dem_step",
                                   number(cs.time.dem_step)};
  for (const auto& [name, value] : cs.liggghts.variables) args.insert(args.end(), {"-var", name, value});
  if (chdir(s.options.case_folder.c_str()) != 0)
    throw cfd::ConfigError("cannot enter the case folder '" + s.options.case_folder + "'");
  s.dem = std::make_unique<LiggghtsInstance>(MPI_COMM_WORLD, args);
  s.dem->runFile(cs.liggghts.script);
  const double script_dt = s.dem->lammps()->update->dt;
  if (std::abs(script_dt - cs.time.dem_step) > 1e-12 * cs.time.dem_step)
    throw cfd::ConfigError("time.dem_step is " + number(cs.time.dem_step) + " s but the LIGGGHTS script sets timestep " +
                           number(script_dt) + " s; use `timestep ${dem_step}` in the script");
  s.parcels = std::make_unique<DemParcels>(s.dem->lammps());
  s.dem->command("run 0");
  s.dem_steps = cs.time.demStepsPerGasStep();
  s.initial_parcels = s.parcels->globalCount();

  std::vector<std::string> columns = {"time"};
  if (cs.monitors.has_bed_pressure_drop) columns.insert(columns.end(), {"bed_pressure_drop", "bed_weight_per_area"});
  for (double z : cs.monitors.pressure_planes) columns.push_back("p_z" + label(z));
  for (double z : cs.monitors.pressure_planes) columns.push_back("gas_fraction_z" + label(z));
  for (int t = 1; t <= s.parcels->ntypes(); ++t) columns.push_back("mean_z_type" + std::to_string(t));
  for (const char* c : {"gas_fraction_min", "gas_fraction_max", "floor_hits", "drag_floored", "drag_invalid",
                        "drag_above_one", "orphans", "lost_parcels", "gas_cfl", "pressure_iterations"})
    columns.emplace_back(c);
  s.monitors = std::make_unique<CsvWriter>((s.output / "monitors.csv").string(), columns, s.rank == 0);

  s.fields = std::make_unique<cfd::FieldWriter>(mesh, s.output.string(), "fields");
  s.progress.end_time = cs.time.end;
  s.wall_start = MPI_Wtime();
  s.next_progress = cs.output.progress_interval;
  if (s.rank == 0)
    std::printf("parcelflow: %ld parcels, %ld gas cells, gas step %g s = %d DEM steps, drag %s, kernel %s; "
                "output in %s\n",
                s.initial_parcels, mesh.nGlobalCells(), cs.time.gas_step, s.dem_steps, cs.coupling.drag.c_str(),
                cs.coupling.kernel.type.c_str(), s.output.c_str());
}

bool CoupledRun::advance() {
  State& s = *s_;
  const CaseSettings& cs = s.case_def.settings;
  const double dt = cs.time.gas_step;
  if (s.time >= cs.time.end - 1e-9 * dt) return false;
  const cfd::Mesh& mesh = s.gas->mesh();
  const int n_owned = mesh.nOwnedCells();

  double t0 = MPI_Wtime();
  const ParcelBatch batch = s.parcels->read();
  s.orphans += static_cast<long>(s.coupler->beginStep(batch).orphans);
  s.coupler->depositSolids(s.solids.solid_fraction);
  s.gas_fraction.resize(n_owned);
  for (int c = 0; c < n_owned; ++c) {
    const double a = 1.0 - s.solids.solid_fraction[c];
    s.min_gas_fraction_seen = std::min(s.min_gas_fraction_seen, a);
    if (a < cs.coupling.gas_fraction_floor) ++s.floor_hits;
    s.gas_fraction[c] = std::max(a, cs.coupling.gas_fraction_floor);
  }
  s.velocity = interleavedOwned(s.gas->velocity(), n_owned);
  const DragStats drag = s.coupler->computeDrag(s.gas_fraction, s.velocity, s.solids, s.at_parcels);
  s.drag_floored += static_cast<long>(drag.alphaGFloored);
  s.drag_invalid += static_cast<long>(drag.invalidInput);
  s.drag_above_one += static_cast<long>(drag.alphaGAboveOne);
  s.gas->setGasFraction(s.gas_fraction);
  s.gas->setDragCoefficient(s.solids.beta);
  s.gas->setDragSource(vectorField(s.solids.beta_us));
  double t1 = MPI_Wtime();
  s.progress.split.add(Phase::coupling, t1 - t0);

  const cfd::StepReport gas_report = s.gas->advance(dt);
  s.pressure_iterations += gas_report.pressureIterations;
  s.preconditioner_builds += gas_report.pressurePreconditionerBuilt ? 1 : 0;
  s.unconverged_solves += gas_report.unconvergedSolves;
  double t2 = MPI_Wtime();
  s.progress.split.add(Phase::gas, t2 - t1);

  s.velocity = interleavedOwned(s.gas->velocity(), n_owned);
  s.grad_p = interleavedOwned(s.gas->pressureGradient(), n_owned);
  s.coupler->gatherGas(s.velocity, s.grad_p, s.at_parcels);
  s.parcels->write(s.at_parcels);
  double t3 = MPI_Wtime();
  s.progress.split.add(Phase::coupling, t3 - t2);

  s.dem->quietCommand("run " + std::to_string(s.dem_steps) + " pre no post no");
  double t4 = MPI_Wtime();
  s.progress.split.add(Phase::dem, t4 - t3);

  ++s.step;
  s.time = s.step * dt;
  s.progress.time = s.time;
  s.progress.parcel_steps += static_cast<double>(s.parcels->globalCount()) * s.dem_steps;

  if (s.time >= s.next_monitor - 1e-9 * dt) {
    s.next_monitor += cs.output.monitor_interval;
    std::vector<double> row = {s.time};
    const std::vector<double> p = s.planes->meansAtHeights(s.gas->pressure(), s.gas->pressureGradient());
    const std::size_t nplanes = cs.monitors.pressure_planes.size();
    if (cs.monitors.has_bed_pressure_drop) {
      // What the pressure drop carries on average in a fluidized bed: the buoyant weight of the parcels
      // above the lower plane, per area (the drop also holds the gas's own rho_g g dz).
      const double g = std::abs(s.case_def.gas.gas.gravity[2]);
      const double weight =
          s.parcels->buoyantWeightAbove(cs.monitors.bed_pressure_drop[0], s.case_def.gas.gas.density, g);
      row.insert(row.end(), {p[nplanes] - p[nplanes + 1], weight / s.planes->layerArea(nplanes)});
    }
    row.insert(row.end(), p.begin(), p.begin() + nplanes);
    const std::vector<double> a = s.planes->means(s.gas_fraction);
    row.insert(row.end(), a.begin(), a.begin() + nplanes);
    for (double z : s.parcels->meanHeightPerType()) row.push_back(z);
    double local_min = 1.0, local_max = 0.0, gmin = 0.0, gmax = 0.0;
    for (int c = 0; c < n_owned; ++c) {
      local_min = std::min(local_min, 1.0 - s.solids.solid_fraction[c]);
      local_max = std::max(local_max, 1.0 - s.solids.solid_fraction[c]);
    }
    MPI_Allreduce(&local_min, &gmin, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
    MPI_Allreduce(&local_max, &gmax, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    const cfd::StepReport& r = s.gas->lastReport();
    row.insert(row.end(), {gmin, gmax, static_cast<double>(sumLong(s.floor_hits, MPI_COMM_WORLD)),
                           static_cast<double>(sumLong(s.drag_floored, MPI_COMM_WORLD)),
                           static_cast<double>(sumLong(s.drag_invalid, MPI_COMM_WORLD)),
                           static_cast<double>(sumLong(s.drag_above_one, MPI_COMM_WORLD)),
                           static_cast<double>(sumLong(s.orphans, MPI_COMM_WORLD)),
                           static_cast<double>(s.initial_parcels - s.parcels->globalCount()), r.cfl,
                           static_cast<double>(r.pressureIterations)});
    s.monitors->row(row);
  }
  if (cs.output.fields_interval > 0.0 && s.time >= s.next_fields - 1e-9 * dt) {
    s.next_fields += cs.output.fields_interval;
    writeFields(s);
  }
  double t5 = MPI_Wtime();
  s.progress.split.add(Phase::output, t5 - t4);
  s.progress.wall_seconds = t5 - s.wall_start;
  if (s.progress.wall_seconds >= s.next_progress) {
    s.next_progress += cs.output.progress_interval;
    if (s.rank == 0) std::printf("%s\n", formatProgress(s.progress).c_str());
  }
  return true;
}

void writeFields(CoupledRun::State& s) {
  const int n_owned = s.gas->mesh().nOwnedCells();
  cfd::VectorField solids_velocity(n_owned, cfd::Vec3::Zero());
  for (int c = 0; c < n_owned; ++c)
    if (s.solids.beta[c] > 0.0)
      for (int d = 0; d < 3; ++d) solids_velocity[c][d] = s.solids.beta_us[3 * c + d] / s.solids.beta[c];
  s.fields->addScalar("gas_fraction", s.gas_fraction);
  s.fields->addVector("gas_velocity", s.gas->velocity());
  s.fields->addScalar("pressure", s.gas->pressure());
  s.fields->addVector("solids_velocity", solids_velocity);
  s.fields->write(s.time);
}

void CoupledRun::finalize() {
  State& s = *s_;
  if (s.case_def.settings.output.fields_interval == 0.0) writeFields(s);
  const long floor_hits = sumLong(s.floor_hits, MPI_COMM_WORLD);
  const long orphans = sumLong(s.orphans, MPI_COMM_WORLD);
  const long drag_floored = sumLong(s.drag_floored, MPI_COMM_WORLD);
  const long drag_invalid = sumLong(s.drag_invalid, MPI_COMM_WORLD);
  const long drag_above_one = sumLong(s.drag_above_one, MPI_COMM_WORLD);
  double min_seen = 1.0;
  MPI_Allreduce(&s.min_gas_fraction_seen, &min_seen, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  const long lost = s.initial_parcels - s.parcels->globalCount();
  if (s.rank == 0) {
    std::printf("%s\n", formatProgress(s.progress).c_str());
    std::printf("parcelflow: done: %ld gas steps, %.3f s simulated in %.1f s wall; lowest gas fraction %.4f; "
                "gas-fraction floor %.3f hit in %ld cell-steps, drag at the floor for %ld parcel-steps, "
                "drag input invalid for %ld and a_g above 1 for %ld parcel-steps; "
                "%ld parcel-steps without a fluid cell; %ld parcels lost\n",
                s.step, s.time, s.progress.wall_seconds, min_seen, s.case_def.settings.coupling.gas_fraction_floor,
                floor_hits, drag_floored, drag_invalid, drag_above_one, orphans, lost);
    std::printf("parcelflow: gas: %.1f pressure iterations per step, pressure preconditioner built in %ld of %ld "
                "steps, %ld linear solves stopped at max_iterations\n",
                s.step > 0 ? static_cast<double>(s.pressure_iterations) / s.step : 0.0, s.preconditioner_builds,
                s.step, s.unconverged_solves);
    std::printf("parcelflow: monitors in %s, fields in %s (open fields.xdmf in ParaView)\n",
                s.monitors->path().c_str(), s.output.c_str());
  }
}

}  // namespace parcelflow::coupling
