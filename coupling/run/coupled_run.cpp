#include "coupling/run/coupled_run.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cfd/base/config_error.hpp"
#include "cfd/fv/diffusion_smoother.hpp"
#include "cfd/fv/excess_solids_spill.hpp"
#include "cfd/output/field_writer.hpp"
#include "cfd/output/gas_checkpoint.hpp"
#include "cfd/solver/gas_solver.hpp"
#include "cfd/io/hdf5_file.hpp"
#include "cfd/mesh/planes_near_cell_faces.hpp"
#include "coupling/run/blowup_guard.h"
#include "coupling/run/case_reader.h"
#include "coupling/run/checkpoint.h"
#include "coupling/run/coupler_view.h"
#include "coupling/dem/dem_engine.h"
#include "coupling/run/geometry_stl.h"
#include "coupling/monitors/monitor_registry.h"
#include "coupling/monitors/monitor_table.h"
#include "coupling/run/output_folder.h"
#include "coupling/run/class_collision_exchange.h"
#include "coupling/run/parcel_mesh_coupler.h"
#include "coupling/output/parcel_writer.h"
#include "coupling/monitors/plane_averages.h"
#include "coupling/run/peak_memory.h"
#include "coupling/run/progress_line.h"
#include "coupling/run/run_counters.h"
#include "coupling/run/run_warnings.h"
#include "coupling/run/side_walls.h"
#include "cfd/base/number_text.hpp"
#include "coupling/run/stop_signal.h"
#include "coupling/run/time_averages.h"

namespace parcelflow::coupling {

namespace fs = std::filesystem;

struct CoupledRun::State {
  RunOptions options;
  CaseDefinition case_def;
  std::map<std::string, std::string> settings;  // the restart-relevant part of case.yaml
  int rank = 0;
  fs::path output;
  std::unique_ptr<FolderLock> output_lock;  // released last, after everything that writes into the folder

  std::unique_ptr<cfd::GasSolver> gas;
  std::unique_ptr<CellOwnerMap> owners;
  std::unique_ptr<ParcelMeshCoupler> coupler;
  std::unique_ptr<DemEngine> dem;
  std::unique_ptr<MonitorTable> monitors;
  std::unique_ptr<cfd::FieldWriter> fields;
  std::unique_ptr<ParcelWriter> parcel_output;
  std::unique_ptr<TimeAverages> averages;  // when monitors.average is set
  std::unique_ptr<RunWarnings> warnings;
  std::unique_ptr<BlowupGuard> guard;
  std::unique_ptr<cfd::DiffusionSmoother> smoother;  // coupling.kernel.smoothing_length > 0
  std::unique_ptr<ClassCollisionExchange> class_collisions;  // coupling.class_collisions
  bool spill_excess_solids = false;                   // coupling.excess_solids: spill

  int dem_steps = 1;
  LoopState loop;        // step, time, next output times (its counters are only used in checkpoints)
  RunCounters counters;  // this rank's
  int stop_signal = 0;
  std::string last_checkpoint;
  bool warned_slow_checkpoint = false;

  double wall_start = 0.0, next_progress = 0.0;
  ProgressState progress;

  SolidsOnCells solids;
  GasAtParcels at_parcels;
  std::vector<double> gas_fraction, velocity, grad_p;
};

namespace {

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

// u_s = sum(w kappa v) / sum(w kappa) per owned cell, interleaved xyz; zero where no parcel drags.
std::vector<double> solidsVelocity(const SolidsOnCells& solids) {
  std::vector<double> us(solids.beta_us.size(), 0.0);
  for (std::size_t c = 0; c < solids.beta.size(); ++c)
    if (solids.beta[c] > 0.0)
      for (int d = 0; d < 3; ++d) us[3 * c + d] = solids.beta_us[3 * c + d] / solids.beta[c];
  return us;
}

bool due(double time, double next, double interval, double dt) { return interval > 0.0 && time >= next - 1e-9 * dt; }

const std::vector<std::string> kFieldScalars = {"gas_fraction", "pressure"};
const std::vector<std::string> kFieldVectors = {"gas_velocity", "solids_velocity"};

}  // namespace

// Gas fraction, gas velocity, pressure and the solids velocity of the owned cells, as one HDF5 snapshot.
void writeFields(CoupledRun::State& s);
void writeParcels(CoupledRun::State& s);
void writeCheckpoint(CoupledRun::State& s);
void restoreCheckpoint(CoupledRun::State& s, const Checkpoint& checkpoint);

CoupledRun::CoupledRun(const RunOptions& options) : s_(std::make_unique<State>()) { s_->options = options; }

CoupledRun::~CoupledRun() = default;

int CoupledRun::stopSignal() const { return s_->stop_signal; }

std::string CoupledRun::lastCheckpoint() const { return s_->last_checkpoint; }

void CoupledRun::initialize() {
  State& s = *s_;
  MPI_Comm_rank(MPI_COMM_WORLD, &s.rank);
  installStartUpSignalHandlers(s.rank);
  // Everything parcelflow reads is checked before any work starts.
  s.case_def = readCase(s.options.case_folder);
  const CaseSettings& cs = s.case_def.settings;
  s.settings = restartRelevantSettings(s.options.case_folder + "/case.yaml");
  std::unique_ptr<Checkpoint> checkpoint;
  if (!s.options.restart.empty()) {
    // absolute: LIGGGHTS runs in the case folder, and the gas state is read after it started
    checkpoint = std::make_unique<Checkpoint>(readCheckpoint(fs::absolute(s.options.restart).string()));
    checkSameSettings(*checkpoint, s.settings);
    checkLoopTime(*checkpoint, cs.time.gas_step);
  }
  applyEndTime(s.case_def.settings.time, s.options.end_time, checkpoint ? checkpoint->loop.time : 0.0);
  s.output = fs::absolute(s.options.output_folder.empty() ? fs::path(s.options.case_folder) / cs.output.folder
                                                          : fs::path(s.options.output_folder));
  if (checkpoint) checkOutputSeries(*checkpoint, s.output.string());
  // A continued run keeps the earlier runs' LIGGGHTS logs.
  const std::string log = checkpoint ? "log.liggghts.from_step_" + std::to_string(checkpoint->loop.step) : "log.liggghts";
  s.output_lock = prepareOutputFolder(s.output.string(),
                                      s.options.output_folder.empty() ? "output.folder" : "--output", MPI_COMM_WORLD);
  s.dem = std::make_unique<DemEngine>(MPI_COMM_WORLD, cs, s.options.case_folder, (s.output / log).string());

  s.gas = std::make_unique<cfd::GasSolver>(s.case_def.gas, MPI_COMM_WORLD);
  const cfd::Mesh& mesh = s.gas->mesh();
  // the monitor heights against the mesh now, before LIGGGHTS fills and settles the bed (the monitors
  // themselves need the parcels)
  PlaneAverages(mesh, cs.monitors.pressure_planes, "monitors.pressure_planes");
  if (cs.monitors.has_bed_pressure_drop)
    PlaneAverages(mesh, {cs.monitors.bed_pressure_drop[0], cs.monitors.bed_pressure_drop[1]},
                  "monitors.bed_pressure_drop");
  s.owners = std::make_unique<CellOwnerMap>(MPI_COMM_WORLD, mesh.background().size(), ownedPiecesOf(mesh));
  const BackgroundGrid grid = backgroundGridOf(mesh);
  TransferKernelOptions kernel_options;
  kernel_options.gaussianSharpness = cs.coupling.kernel.sharpness;
  kernel_options.gaussianRadius = cs.coupling.kernel.radius;
  kernel_options.gaussianIsotropic = cs.coupling.kernel.length_scale == "cell_volume";
  for (int d = 0; d < 3; ++d) kernel_options.gaussianSpacing[d] = grid.spacing[d];
  kernel_options.gaussianParcelFactor = cs.coupling.kernel.parcel_scale;
  kernel_options.gaussianReflectAtWalls = cs.coupling.kernel.boundary == "reflect";
  DragLawContext drag_context;  // per-case constants of the filtered law (the others ignore them)
  drag_context.filterSize =
      cs.coupling.filtered_drag.filter_cells * std::cbrt(grid.spacing[0] * grid.spacing[1] * grid.spacing[2]);
  drag_context.gravity = s.case_def.gas.gas.gravity.norm();
  drag_context.particleDensity = cs.coupling.filtered_drag.particle_density;
  s.coupler = std::make_unique<ParcelMeshCoupler>(
      grid, *s.owners, makeTransferKernel(cs.coupling.kernel.type, kernel_options),
      makeDragLaw(cs.coupling.drag, drag_context), DragLimits{cs.coupling.gas_fraction_floor},
      GasProperties{s.case_def.gas.gas.density, s.case_def.gas.gas.viscosity});

  if (cs.coupling.kernel.smoothing_length > 0.0)
    s.smoother = std::make_unique<cfd::DiffusionSmoother>(mesh, cs.coupling.kernel.smoothing_length);
  s.spill_excess_solids = cs.coupling.excess_solids == "spill";

  s.dem->start(checkpoint ? checkpoint->paths.dem : std::string(),
               writeGeometryStl(s.case_def.gas, s.output.string(), MPI_COMM_WORLD));
  s.dem_steps = cs.time.demStepsPerGasStep();
  if (cs.coupling.class_collisions.enabled)
    s.class_collisions = std::make_unique<ClassCollisionExchange>(
        MPI_COMM_WORLD, s.dem->parcels().ntypes(),
        ClassCollisionParameters{cs.coupling.class_collisions.restitution, cs.coupling.class_collisions.friction});
  s.loop.initial_parcels = s.dem->parcels().globalCount();
  KernelReach kernel_reach;
  if (cs.coupling.kernel.type == GaussianKernel::typeName)  // h of the cell_volume length scale
    kernel_reach.length = std::cbrt(grid.spacing[0] * grid.spacing[1] * grid.spacing[2]);
  kernel_reach.parcel_scale = cs.coupling.kernel.parcel_scale;
  kernel_reach.smoothing_length = cs.coupling.kernel.smoothing_length;
  kernel_reach.spills_excess = s.spill_excess_solids;
  kernel_reach.class_collisions = cs.coupling.class_collisions.enabled;
  kernel_reach.keeps_shear_stress = s.dem->parcels().keepsShearStress();
  const std::array<bool, 3> dem_periodic = s.dem->periodicAxes();
  kernel_reach.narrowest_extent = narrowestExtentBetweenWalls(
      {grid.spacing[0] * grid.cells[0], grid.spacing[1] * grid.cells[1], grid.spacing[2] * grid.cells[2]}, dem_periodic);
  kernel_reach.side_wall_area_per_volume =
      sideWallAreaPerVolume(mesh, s.case_def.gas.boundaries, s.case_def.gas.gas.gravity, dem_periodic);
  const cfd::LinearSolverSettings& pressure = s.case_def.gas.solver.pressure;
  const std::string pressure_stop_rule =
      pressure.criterion == cfd::StoppingCriterion::Strict
          ? "max(tolerance |b|, solver.pressure.absolute_tolerance = " + cfd::shortNumber(pressure.absTolerance) +
                "); a loose absolute_tolerance leaves the pressure unsolved"
          : "solver.pressure.tolerance = " + cfd::shortNumber(pressure.tolerance) +
                " of the through-flow (criterion normalized): the step's continuity error was that small already";
  s.warnings = std::make_unique<RunWarnings>(MPI_COMM_WORLD, mesh, *s.owners, s.loop.initial_parcels,
                                             pressure_stop_rule, kernel_reach,
                                             s.case_def.gas.geometry.items().empty() ? nullptr : &s.case_def.gas.geometry);
  s.guard = std::make_unique<BlowupGuard>(MPI_COMM_WORLD, cs.coupling.guards, s.loop.initial_parcels);
  s.loop.next_checkpoint = cs.output.checkpoint_interval;  // the other output times start at 0
  if (!checkpoint) clearEarlierRun(s.output.string(), MPI_COMM_WORLD);
  s.fields = std::make_unique<cfd::FieldWriter>(mesh, s.output.string(), cfd::series::fields);
  s.parcel_output = std::make_unique<ParcelWriter>(MPI_COMM_WORLD, s.output.string(), cfd::series::parcels);
  if (cs.monitors.averages())
    s.averages = std::make_unique<TimeAverages>(mesh, cs.monitors.pressure_planes, cs.monitors.average_start,
                                                std::abs(s.case_def.gas.gas.gravity[2]), s.output.string());
  if (checkpoint) restoreCheckpoint(s, *checkpoint);
  s.monitors = std::make_unique<MonitorTable>(
      makeMonitors(cs.monitors, mesh, s.case_def.gas, s.dem->parcels()), (s.output / "monitors.csv").string(),
      s.rank == 0, checkpoint ? checkpoint->loop.monitor_bytes : -1);

  s.progress.end_time = cs.time.end;
  s.progress.time = s.progress.start_time = s.loop.time;
  s.wall_start = MPI_Wtime();
  s.next_progress = cs.output.progress_interval;
  installStopSignalHandlers();
  // MPI's profiling hook: a no-op unless a PMPI tool listens (tests/regression/scaling counts the loop's
  // traffic between the two calls).
  MPI_Pcontrol(1);
  const bool cutCells = s.case_def.gas.mesh.walls == cfd::WallRepresentation::CutCells;
  if (s.rank == 0)
    std::printf("parcelflow: %ld parcels, %ld gas cells%s, gas step %g s = %d DEM steps, drag %s, kernel %s; "
                "output in %s%s\n",
                s.dem->parcels().globalCount(), mesh.nGlobalCells(),
                cutCells ? (" (cut cells; " + std::to_string(mesh.mergedCells()) + " small ones merged)").c_str() : "",
                cs.time.gas_step, s.dem_steps, cs.coupling.drag.c_str(), cs.coupling.kernel.type.c_str(),
                s.output.c_str(),
                checkpoint ? (" (continuing checkpoint " + checkpoint->id + " at t = " +
                              std::to_string(s.loop.time) + " s)").c_str()
                           : "");
  if (s.rank == 0 && mesh.unmergedSmallCells() > 0)
    std::printf("parcelflow: warning: %ld cut cells under mesh.small_cell_fraction %g share no open face with a "
                "larger cell and stay alone: small cells slow the pressure solve and their centroids lie close to "
                "their faces; a finer mesh or a smoother geometry there avoids them\n",
                mesh.unmergedSmallCells(), s.case_def.gas.mesh.smallCellFraction);
  if (s.rank == 0 && cutCells)
    for (const std::string& plane : cfd::planesNearCellFaces(s.case_def.gas.mesh, s.case_def.gas.geometry))
      std::printf("parcelflow: warning: %s: on cut cells it leaves a film of fluid across the faces beyond it, which "
                  "can carry spurious gas speeds (the full FCC case diverged so: cfd/README.md, \"Known defect: a "
                  "wall a hair off a cell face\"); move the plane onto the face or into the cell, or mesh.lengths\n",
                  plane.c_str());
}

bool CoupledRun::advance() {
  State& s = *s_;
  const CaseSettings& cs = s.case_def.settings;
  const double dt = cs.time.gas_step;
  if (s.loop.time >= cs.time.end - 1e-9 * dt) return false;
  const cfd::Mesh& mesh = s.gas->mesh();
  const int n_owned = mesh.nOwnedCells();
  DemParcels& parcels = s.dem->parcels();

  double t0 = MPI_Wtime();
  const ParcelBatch batch = parcels.read();
  const TransferStats transfer = s.coupler->beginStep(batch);
  s.counters.orphans += static_cast<long>(transfer.orphans);
  s.counters.fallbacks += static_cast<long>(transfer.fallbacks);
  s.coupler->depositSolids(s.solids.solid_fraction);
  if (s.smoother) s.smoother->apply(s.solids.solid_fraction);
  if (s.spill_excess_solids)
    s.counters.floor_spills +=
        cfd::spillExcessSolids(mesh, s.solids.solid_fraction, 1.0 - cs.coupling.gas_fraction_floor).cells;
  s.gas_fraction.resize(n_owned);
  for (int c = 0; c < n_owned; ++c) {
    const double a = 1.0 - s.solids.solid_fraction[c];
    s.counters.min_gas_fraction = std::min(s.counters.min_gas_fraction, a);
    if (a < cs.coupling.gas_fraction_floor) ++s.counters.floor_hits;
    s.gas_fraction[c] = std::max(a, cs.coupling.gas_fraction_floor);
  }
  s.velocity = interleavedOwned(s.gas->velocity(), n_owned);
  const DragStats drag = s.coupler->computeDrag(s.gas_fraction, s.velocity, s.solids, s.at_parcels);
  s.counters.drag_floored += static_cast<long>(drag.alphaGFloored);
  s.counters.drag_invalid += static_cast<long>(drag.invalidInput);
  s.counters.drag_above_one += static_cast<long>(drag.alphaGAboveOne);
  s.counters.drag_filter_clamped += static_cast<long>(drag.filterCorrectionClamped);
  if (s.class_collisions) s.class_collisions->computeForces(*s.coupler, s.gas_fraction, dt, s.at_parcels.class_force);
  s.gas->setGasFraction(s.gas_fraction);
  s.gas->setDragCoefficient(s.solids.beta);
  s.gas->setDragSource(vectorField(s.solids.beta_us));
  double t1 = MPI_Wtime();
  s.progress.split.add(Phase::coupling, t1 - t0);

  const cfd::StepReport gas_report = s.gas->advance(dt);
  s.counters.pressure_iterations += gas_report.pressureIterations;
  s.counters.preconditioner_builds += gas_report.pressurePreconditionerBuilt ? 1 : 0;
  s.counters.unconverged_solves += gas_report.unconvergedSolves;
  s.warnings->afterGasStep(batch, parcels.ids(), gas_report, parcels.globalCount(), s.loop.time + dt,
                           s.loop.step + 1);
  s.guard->check(s.gas.get(), gas_report, parcels.globalCount(), s.loop.time + dt, s.loop.step + 1,
                 s.last_checkpoint);
  double t2 = MPI_Wtime();
  s.progress.split.add(Phase::gas, t2 - t1);

  s.velocity = interleavedOwned(s.gas->velocity(), n_owned);
  s.grad_p = interleavedOwned(s.gas->pressureGradient(), n_owned);
  s.coupler->gatherGas(s.velocity, s.grad_p, s.at_parcels);
  parcels.write(s.at_parcels);
  double t3 = MPI_Wtime();
  s.progress.split.add(Phase::coupling, t3 - t2);

  s.dem->advance(s.dem_steps);
  double t4 = MPI_Wtime();
  s.progress.split.add(Phase::dem, t4 - t3);

  ++s.loop.step;
  s.loop.time = s.loop.step * dt;
  s.guard->check(nullptr, gas_report, parcels.globalCount(), s.loop.time, s.loop.step, s.last_checkpoint);
  if (s.averages) s.averages->add(s.loop.time, dt, *s.gas, s.solids.solid_fraction, solidsVelocity(s.solids));
  s.progress.time = s.loop.time;
  s.progress.parcel_steps += static_cast<double>(parcels.globalCount()) * s.dem_steps;

  if (due(s.loop.time, s.loop.next_monitor, cs.output.monitor_interval, dt)) {
    s.loop.next_monitor += cs.output.monitor_interval;
    s.monitors->sample({s.loop.time, *s.gas, parcels, s.gas_fraction, s.solids.solid_fraction, s.counters,
                        s.loop.initial_parcels});
  }
  if (due(s.loop.time, s.loop.next_fields, cs.output.fields_interval, dt)) {
    s.loop.next_fields += cs.output.fields_interval;
    writeFields(s);
  }
  if (due(s.loop.time, s.loop.next_parcels, cs.output.parcels_interval, dt)) {
    s.loop.next_parcels += cs.output.parcels_interval;
    writeParcels(s);
  }
  s.stop_signal = stopRequested(MPI_COMM_WORLD);
  if (s.stop_signal || due(s.loop.time, s.loop.next_checkpoint, cs.output.checkpoint_interval, dt)) {
    if (cs.output.checkpoint_interval > 0.0)
      while (s.loop.next_checkpoint <= s.loop.time + 1e-9 * dt) s.loop.next_checkpoint += cs.output.checkpoint_interval;
    writeCheckpoint(s);
  }
  double t5 = MPI_Wtime();
  s.progress.split.add(Phase::output, t5 - t4);
  s.progress.wall_seconds = t5 - s.wall_start;
  if (s.progress.wall_seconds >= s.next_progress) {
    s.next_progress += cs.output.progress_interval;
    if (s.rank == 0) std::printf("%s\n", formatProgress(s.progress).c_str());
  }
  return s.stop_signal == 0;
}

void writeFields(CoupledRun::State& s) {
  const cfd::VectorField solids_velocity = vectorField(solidsVelocity(s.solids));
  s.fields->addScalar(kFieldScalars[0], s.gas_fraction);
  s.fields->addScalar(kFieldScalars[1], s.gas->pressure());
  s.fields->addVector(kFieldVectors[0], s.gas->velocity());
  s.fields->addVector(kFieldVectors[1], solids_velocity);
  s.fields->write(s.loop.time);
}

void writeParcels(CoupledRun::State& s) {
  DemParcels& parcels = s.dem->parcels();
  const ParcelBatch batch = parcels.read();
  ParcelSnapshot snap;
  snap.x.assign(batch.x, batch.x + 3 * batch.size);
  snap.v.assign(batch.v, batch.v + 3 * batch.size);
  snap.dp.assign(batch.dp, batch.dp + batch.size);
  snap.np.assign(batch.np, batch.np + batch.size);
  snap.type = parcels.types();
  snap.id.assign(parcels.ids().begin(), parcels.ids().end());
  s.parcel_output->write(s.loop.time, snap);
}

// After every output of the step (Lethe #1097: a checkpoint taken before the end-of-step updates stores a
// stale state).
void writeCheckpoint(CoupledRun::State& s) {
  const double start = MPI_Wtime();
  const CheckpointDraft draft = beginCheckpoint(s.output.string(), s.loop.step, MPI_COMM_WORLD);
  s.dem->writeRestart(draft.partial.dem);
  cfd::writeGasCheckpoint(*s.gas, draft.partial.gas, draft.id);
  // The restarted run builds a new pressure preconditioner; so does this one, and both solve alike.
  s.gas->rebuildPreconditionerNextStep();
  LoopState loop = s.loop;
  loop.dem_step = s.dem->step();
  loop.parcels = s.dem->parcels().globalCount();
  loop.monitor_bytes = s.monitors->csv().bytes();
  loop.field_times = s.fields->snapshotTimes();
  loop.parcel_snapshots = s.parcel_output->snapshots();
  loop.counters = s.counters.totals(MPI_COMM_WORLD);
  if (s.averages) {
    loop.averages = s.averages->save(draft.partial.folder + "/averages.h5", draft.id);
    s.averages->write(s.loop.time);
  }
  commitCheckpoint(draft, loop, s.settings, MPI_COMM_WORLD);
  s.last_checkpoint = draft.final.folder;
  if (s.rank == 0) std::printf("parcelflow: checkpoint %s at t = %.6g s in %s\n", draft.id.c_str(), s.loop.time,
                               draft.final.folder.c_str());
  // A checkpoint slower than mpirun's grace after a signal would be cut off by its SIGKILL (measured: a
  // 67,500-parcel checkpoint lost that way). Said once, as soon as it is known.
  const double seconds = MPI_Wtime() - start, grace = mpirunKillDelay();
  if (s.rank == 0 && grace >= 0.0 && seconds > grace && !s.warned_slow_checkpoint)
    std::printf("parcelflow: warning: this checkpoint took %.3g s, but Open MPI's mpirun kills the ranks %g s after "
                "it forwards a signal (odls_base_sigkill_timeout): a SIGTERM or Ctrl-C to mpirun would lose the "
                "checkpoint of that stop. Send the signal to the parcelflow processes instead (pkill -TERM -x "
                "parcelflow), or start with mpirun --mca odls_base_sigkill_timeout %.0f\n",
                seconds, grace, std::ceil(10.0 * seconds + 10.0));
  s.warned_slow_checkpoint = s.warned_slow_checkpoint || seconds > grace;
}

void restoreCheckpoint(CoupledRun::State& s, const Checkpoint& checkpoint) {
  const LoopState& saved = checkpoint.loop;
  DemParcels& parcels = s.dem->parcels();
  if (s.dem->step() != saved.dem_step)
    throw cfd::ConfigError(
        "liggghts.script", s.case_def.settings.liggghts.script,
        "a script that reads ${restart_file} when ${restarting} is 1 and then skips its filling and settling (after "
        "it ran LIGGGHTS is at step " + std::to_string(s.dem->step()) + ", the checkpoint at step " +
        std::to_string(saved.dem_step) + "; coupling/README.md, Checkpoints)");
  if (parcels.globalCount() != saved.parcels)
    throw cfd::ConfigError("--restart " + checkpoint.paths.folder, std::to_string(saved.parcels) + " parcels",
                           "the " + std::to_string(parcels.globalCount()) + " parcels LIGGGHTS has after the script");
  cfd::readGasCheckpoint(*s.gas, checkpoint.paths.gas, checkpoint.id);
  s.loop = saved;
  // Per-rank counters continue on rank 0 (their sums are what is reported); the others start from zero.
  s.counters = saved.counters;
  if (s.rank != 0)
    for (auto& field : s.counters.perRank()) *field.second = 0;
  s.fields->continueSeries(saved.field_times, kFieldScalars, kFieldVectors);
  s.parcel_output->continueSeries(saved.parcel_snapshots);
  if (s.averages) s.averages->restore(saved.averages, checkpoint.paths.folder + "/averages.h5", checkpoint.id);
  s.last_checkpoint = checkpoint.paths.folder;
}

void CoupledRun::finalize() {
  MPI_Pcontrol(0);
  State& s = *s_;
  if (s.case_def.settings.output.fields_interval == 0.0) writeFields(s);
  if (s.averages) s.averages->write(s.loop.time);
  const RunCounters total = s.counters.totals(MPI_COMM_WORLD);
  const long lost = s.loop.initial_parcels - s.dem->parcels().globalCount();
  const PeakMemory memory = peakMemory(MPI_COMM_WORLD);
  double mine[4], low[4], high[4];
  for (int p = 0; p < 4; ++p) mine[p] = s.progress.split.seconds(static_cast<Phase>(p));
  MPI_Allreduce(mine, low, 4, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  MPI_Allreduce(mine, high, 4, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  WallClockSplit fastest, slowest;
  for (int p = 0; p < 4; ++p) {
    fastest.add(static_cast<Phase>(p), low[p]);
    slowest.add(static_cast<Phase>(p), high[p]);
  }
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (s.rank == 0) {
    std::printf("%s\n", formatProgress(s.progress).c_str());
    std::printf("parcelflow: done: %ld gas steps, %.6g s simulated in %.1f s wall; lowest gas fraction %.4f; "
                "gas-fraction floor %.3f hit in %ld cell-steps (solids above it moved to neighbours in %ld), "
                "drag at the floor for %ld parcel-steps, "
                "drag input invalid for %ld and a_g above 1 for %ld parcel-steps, filtered-drag correction "
                "bounded for %ld; "
                "%ld parcel-steps without a fluid cell, %ld in a neighbouring cell (centroid kernel); "
                "%ld parcels lost\n",
                s.loop.step, s.loop.time, s.progress.wall_seconds, total.min_gas_fraction,
                s.case_def.settings.coupling.gas_fraction_floor, total.floor_hits, total.floor_spills,
                total.drag_floored, total.drag_invalid, total.drag_above_one, total.drag_filter_clamped,
                total.orphans, total.fallbacks, lost);
    std::printf("parcelflow: gas: %.1f pressure iterations per step, pressure preconditioner built in %ld of %ld "
                "steps, %ld linear solves stopped at max_iterations\n",
                s.loop.step > 0 ? static_cast<double>(total.pressure_iterations) / s.loop.step : 0.0,
                total.preconditioner_builds, s.loop.step, total.unconverged_solves);
    if (s.class_collisions)
      std::printf("parcelflow: class collisions (coupling.class_collisions): %ld cell-steps of a pair of classes "
                  "left uncorrected (their parcels exchange more than their particles)\n",
                  s.class_collisions->uncorrected());
    std::printf("parcelflow: peak memory per rank: largest %.1f MB (rank %d), smallest %.1f MB\n",
                memory.largest_mb, memory.largest_rank, memory.smallest_mb);
    if (ranks > 1)
      std::printf("parcelflow: wall time per phase, fastest-slowest rank: %s\n",
                  formatSplitRange(fastest, slowest).c_str());
    if (s.averages && s.averages->averagedTime() > 0.0)
      std::printf("parcelflow: time averages over %.4g s: bed height %.4g m (averages.csv, averages.xdmf)\n",
                  s.averages->averagedTime(), s.averages->bedHeight());
    else if (s.averages)
      std::printf("parcelflow: no time averages: the run ended at t = %.4g s, before monitors.average.start = "
                  "%.4g s (averages.csv holds no values)\n",
                  s.loop.time, s.case_def.settings.monitors.average_start);
    std::printf("parcelflow: monitors in %s, fields in %s (open fields.xdmf in ParaView)\n",
                s.monitors->csv().path().c_str(), s.output.c_str());
  }
}

}  // namespace parcelflow::coupling
