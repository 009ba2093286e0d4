// Gas solver benchmark (not a test): wall time per gas step and Krylov iterations for the 47 x 5 x 94
// pseudo-2D box and a ~50,000-cell cylinder column with a ring sparger, each with a frozen dense bed in
// its lower part. Run with 1 and 2 ranks: mpirun -np N cfd_gas_benchmark
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "cfd/gas_solver.hpp"

using namespace parcelflow::cfd;

namespace {
void run(const std::string& label, GasSettings settings, double bedTop, double dt,
         PreconditionerType pressurePreconditioner) {
  settings.solver.pressure.preconditioner = pressurePreconditioner;
  GasSolver gas(settings, MPI_COMM_WORLD);
  const Mesh& m = gas.mesh();
  ScalarField alpha(m.nLocalCells()), beta(m.nLocalCells());
  for (int c = 0; c < m.nLocalCells(); ++c) {
    const bool bed = m.cellCentre(c)[2] < bedTop;
    alpha[c] = bed ? 0.45 : 1.0;
    beta[c] = bed ? 1.5e4 : 0.0;
  }
  gas.setGasFraction(alpha);
  gas.setDragCoefficient(beta);
  gas.setDragSource(VectorField(m.nLocalCells(), Vec3::Zero()));
  const int warmup = 5, steps = 20;
  for (int i = 0; i < warmup; ++i) gas.advance(dt);
  long mom = 0, pres = 0, unconverged = 0;
  double cfl = 0;
  MPI_Barrier(MPI_COMM_WORLD);
  const double t0 = MPI_Wtime();
  for (int i = 0; i < steps; ++i) {
    const StepReport r = gas.advance(dt);
    mom += r.momentumIterations;
    pres += r.pressureIterations;
    unconverged += r.unconvergedSolves;
    cfl = r.cfl;
  }
  MPI_Barrier(MPI_COMM_WORLD);
  const double perStep = (MPI_Wtime() - t0) / steps;
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (rank == 0)
    std::printf("%-16s %-14s ranks %d  cells %7ld  dt %.1e  time/step %8.2f ms  momentum its/step %5.1f"
                "  pressure its/step %5.1f  CFL %.3f  unconverged %ld\n",
                label.c_str(),
                pressurePreconditioner == PreconditionerType::BlockCholesky ? "block_cholesky"
                                                                            : "block_ic",
                size, m.nGlobalCells(), dt, 1e3 * perStep,
                static_cast<double>(mom) / steps, static_cast<double>(pres) / steps, cfl,
                unconverged);
  std::fflush(stdout);
}

GasSettings box() {
  GasSettings s;
  s.mesh.lengths = Vec3(0.15, 0.016, 0.30);
  s.mesh.cells = {47, 5, 94};
  s.boundaries = {{"zmin", BoundaryType::VelocityInlet, Vec3(0, 0, 0.5), 0.0},
                  {"zmax", BoundaryType::PressureOutlet, Vec3::Zero(), 1e5},
                  {"xmin", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0},
                  {"xmax", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0},
                  {"ymin", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0},
                  {"ymax", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0}};
  return s;
}

GasSettings column() {
  GasSettings s;
  s.mesh.origin = Vec3(-0.16, -0.16, 0.0);
  s.mesh.lengths = Vec3(0.32, 0.32, 0.70);
  s.mesh.cells = {32, 32, 70};
  s.geometry = Geometry({{Geometry::Op::Union, Primitive::cylinder(0, 0, 0.15, 0, 0.7), ""}});
  s.boundaries = {{"zmin", BoundaryType::VelocityInlet, Vec3(0, 0, 0.2), 0.0},
                  {"zmax", BoundaryType::PressureOutlet, Vec3::Zero(), 1e5},
                  {"walls", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0}};
  InletRegionSettings ring;
  ring.name = "sparger";
  ring.region = Geometry({{Geometry::Op::Union, Primitive::cylinder(0, 0, 0.10, 0.03, 0.05), ""},
                          {Geometry::Op::Cut, Primitive::cylinder(0, 0, 0.07, 0.0, 0.1), ""}});
  ring.flowRate = 5e-3;
  ring.velocity = Vec3(0, 0, -5);
  s.inletRegions = {ring};
  return s;
}
}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  // block_cholesky (complete factorisation of each rank's block) is far slower to factorise at this
  // size, so the benchmark uses the default incomplete Cholesky.
  run("box 47x5x94", box(), 0.15, 5e-4, PreconditionerType::BlockIncompleteCholesky);
  run("cylinder column", column(), 0.35, 5e-4, PreconditionerType::BlockIncompleteCholesky);
  MPI_Finalize();
  return 0;
}
