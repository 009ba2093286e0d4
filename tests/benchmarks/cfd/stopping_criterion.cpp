// Measurement (not a test, no timing): what the stopping criterion of the linear solves changes on the
// Goldschmidt bed's mesh (cases/goldschmidt_segregation: 0.15 x 0.015 x 0.3 m, 47 x 5 x 94, 1.1 m/s, gas
// step 5e-4 s). A bubbling bed (a_g 0.25-0.55 and a bubble, Ergun's beta) moves up at 0.5 m/s, so every
// step has a changing gas fraction to balance, as in the coupled run. Each rule runs the same 40 steps
// after 5; printed per step: pressure and momentum iterations, the continuity error (mean and largest),
// and at the end the largest difference of p (against the bed's pressure drop) and u (against the largest
// |u|) from the strict run. The strict run with half the gas step, at the same time, shows the size of the
// time-step error the criteria are compared with. Run by hand: mpirun -np 1|2 cfd_stopping_criterion
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "cfd/solver/gas_solver.hpp"

using namespace parcelflow::cfd;

namespace {
constexpr double kU = 1.1, kDt = 5e-4, kBedSpeed = 0.5;
constexpr int kWarmup = 5, kSteps = 40;

// Gas fraction and Ergun drag of the bed at time t.
void setBed(GasSolver& gas, double t) {
  const Mesh& m = gas.mesh();
  ScalarField alpha(m.nLocalCells()), beta(m.nLocalCells());
  for (int c = 0; c < m.nLocalCells(); ++c) {
    const Vec3& x = m.cellCentre(c);
    const double z = x[2] - kBedSpeed * t;
    double a = 1.0;
    if (x[2] < 0.1) {
      const bool bubble = (Vec3(x[0], 0, z) - Vec3(0.075, 0, 0.04)).norm() < 0.015;
      a = bubble ? 0.95 : 0.4 + 0.15 * std::sin(40.0 * x[0]) * std::cos(30.0 * z);
    }
    const double as = 1.0 - a, dp = 2e-3, mu = 1.8e-5, rho = 1.2;
    alpha[c] = a;
    beta[c] = 150.0 * as * as * mu / (a * dp * dp) + 1.75 * as * rho * (kU / a) / dp;
  }
  gas.setGasFraction(alpha);
  gas.setDragCoefficient(beta);
}

GasSettings goldschmidt() {
  GasSettings s;
  s.mesh.lengths = Vec3(0.15, 0.015, 0.3);
  s.mesh.cells = {47, 5, 94};
  s.boundaries = {{"zmin", BoundaryType::VelocityInlet, Vec3(0, 0, kU), 0.0},
                  {"zmax", BoundaryType::PressureOutlet, Vec3::Zero(), 0.0},
                  {"xmin", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0},
                  {"xmax", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0},
                  {"ymin", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0},
                  {"ymax", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0}};
  return s;
}

struct Fields {
  ScalarField p;
  VectorField u;
};

Fields run(const std::string& label, const SolverSettings& solver, int substeps = 1) {
  GasSettings settings = goldschmidt();
  settings.solver = solver;
  GasSolver gas(settings, MPI_COMM_WORLD);
  const Mesh& m = gas.mesh();
  gas.setDragSource(VectorField(m.nLocalCells(), Vec3::Zero()));
  setBed(gas, 0.0);
  const double dt = kDt / substeps;
  double t = 0.0;
  long pres = 0, mom = 0, unconverged = 0;
  double continuitySum = 0.0, continuityMax = 0.0;
  for (int i = 0; i < (kWarmup + kSteps) * substeps; ++i) {
    t += dt;
    setBed(gas, t);
    const StepReport r = gas.advance(dt);
    if (i < kWarmup * substeps) continue;
    pres += r.pressureIterations;
    mom += r.momentumIterations;
    unconverged += r.unconvergedSolves;
    continuitySum += r.continuityError;
    continuityMax = std::max(continuityMax, r.continuityError);
  }
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const double n = kSteps * substeps;
  if (rank == 0)
    std::printf("%-44s ranks %d  pressure its/step %5.1f  momentum its/step %5.1f  continuity error mean %.2e"
                " max %.2e  unconverged %ld\n",
                label.c_str(), size, pres / n, mom / n, continuitySum / n, continuityMax, unconverged);
  const int nOwned = m.nOwnedCells();
  return {ScalarField(gas.pressure().begin(), gas.pressure().begin() + nOwned),
          VectorField(gas.velocity().begin(), gas.velocity().begin() + nOwned)};
}

void printDifference(const std::string& label, const Fields& a, const Fields& ref) {
  double dp = 0, pLo = 1e300, pHi = -1e300, du = 0, uMax = 0;
  for (std::size_t c = 0; c < ref.p.size(); ++c) {
    dp = std::max(dp, std::abs(a.p[c] - ref.p[c]));
    pLo = std::min(pLo, ref.p[c]);
    pHi = std::max(pHi, ref.p[c]);
    du = std::max(du, (a.u[c] - ref.u[c]).norm());
    uMax = std::max(uMax, ref.u[c].norm());
  }
  pLo = -pLo;
  for (double* v : {&dp, &pLo, &pHi, &du, &uMax}) MPI_Allreduce(MPI_IN_PLACE, v, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf("%-44s against strict: max |dp| / bed dp %.1e  max |du| / max |u| %.1e\n", label.c_str(),
                dp / (pHi + pLo), du / uMax);
}

SolverSettings normalized(double pTol, double pRelTol, double uTol, double uRelTol) {
  SolverSettings s;
  s.pressure.criterion = s.momentum.criterion = StoppingCriterion::Normalized;
  s.pressure.tolerance = pTol;
  s.pressure.relTol = pRelTol;
  s.pressure.finalRelTol = 0.0;
  s.momentum.tolerance = uTol;
  s.momentum.relTol = uRelTol;
  return s;
}

std::string label(double pTol, double pRelTol, double uTol, double uRelTol) {
  char text[128];
  std::snprintf(text, sizeof text, "normalized p %.0e/%.2g/0 u %.0e/%.2g", pTol, pRelTol, uTol, uRelTol);
  return text;
}
}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  SolverSettings strictSettings;
  strictSettings.pressure.criterion = strictSettings.momentum.criterion = StoppingCriterion::Strict;
  const Fields strict = run("strict 1e-8", strictSettings);
  printDifference("strict 1e-8, half the gas step", run("strict 1e-8, half the gas step", strictSettings, 2),
                  strict);
  const double rules[][4] = {{1e-6, 0.0, 1e-6, 0.0}, {1e-6, 0.05, 1e-6, 0.0}, {1e-6, 0.05, 1e-5, 0.1},
                             {1e-5, 0.05, 1e-5, 0.1}, {1e-7, 0.05, 1e-6, 0.0}};
  for (const auto& r : rules) {
    const std::string name = label(r[0], r[1], r[2], r[3]);
    printDifference(name, run(name, normalized(r[0], r[1], r[2], r[3])), strict);
  }
  MPI_Finalize();
  return 0;
}
