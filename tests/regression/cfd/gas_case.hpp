#pragma once
// Helpers shared by the gas verification tests: build settings in code, gather owned cell values by
// global id on rank 0, and compare a run on all ranks with the same run on rank 0 alone.
#include <mpi.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "cfd/solver/gas_solver.hpp"

namespace parcelflow::cfd::testing {

// Cell values of a run, indexed by global cell id (valid on rank 0 only).
struct GlobalFields {
  std::vector<double> p, ux, uy, uz, alpha;
  std::vector<Vec3> centre;
};

inline GlobalFields gather(const GasSolver& gas) {
  const Mesh& m = gas.mesh();
  const int nOwned = m.nOwnedCells();
  std::vector<double> local;
  for (int c = 0; c < nOwned; ++c) {
    const auto& u = gas.velocity()[c];
    const auto& x = m.cellCentre(c);
    local.insert(local.end(), {static_cast<double>(m.globalId(c)), gas.pressure()[c], u[0], u[1],
                               u[2], gas.gasFraction()[c], x[0], x[1], x[2]});
  }
  int count = static_cast<int>(local.size()), size = 1, rank = 0;
  MPI_Comm_size(m.comm(), &size);
  MPI_Comm_rank(m.comm(), &rank);
  std::vector<int> counts(size), displ(size + 1, 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, m.comm());
  for (int r = 0; r < size; ++r) displ[r + 1] = displ[r] + counts[r];
  std::vector<double> all(rank == 0 ? displ[size] : 0);
  MPI_Gatherv(local.data(), count, MPI_DOUBLE, all.data(), counts.data(), displ.data(), MPI_DOUBLE, 0,
              m.comm());
  GlobalFields g;
  if (rank != 0) return g;
  const std::size_t n = m.nGlobalCells();
  g.p.resize(n);
  g.ux.resize(n);
  g.uy.resize(n);
  g.uz.resize(n);
  g.alpha.resize(n);
  g.centre.resize(n);
  for (std::size_t i = 0; i < all.size(); i += 9) {
    const auto id = static_cast<std::size_t>(all[i]);
    g.p[id] = all[i + 1];
    g.ux[id] = all[i + 2];
    g.uy[id] = all[i + 3];
    g.uz[id] = all[i + 4];
    g.alpha[id] = all[i + 5];
    g.centre[id] = Vec3(all[i + 6], all[i + 7], all[i + 8]);
  }
  return g;
}

// Largest difference of p and u between two runs, relative to max(largest |u| of `ref`, uScale) and
// max(largest |p| of `ref`, pScale): the scales are the case's own, for fields that are near zero.
inline double relativeDifference(const GlobalFields& a, const GlobalFields& ref, double pScale,
                                 double uScale) {
  double dp = 0, pmax = 0, du = 0, umax = 0;
  for (std::size_t i = 0; i < ref.p.size(); ++i) {
    dp = std::max(dp, std::abs(a.p[i] - ref.p[i]));
    pmax = std::max(pmax, std::abs(ref.p[i]));
    const Vec3 ua(a.ux[i], a.uy[i], a.uz[i]), ur(ref.ux[i], ref.uy[i], ref.uz[i]);
    du = std::max(du, (ua - ur).norm());
    umax = std::max(umax, ur.norm());
  }
  pmax = std::max(pmax, pScale);
  umax = std::max(umax, uScale);
  return std::max(pmax > 0 ? dp / pmax : dp, umax > 0 ? du / umax : du);
}

// Runs `run` on `comm` and returns the gathered fields (rank 0 of comm).
using CaseRun = std::function<GlobalFields(MPI_Comm)>;

// On more than one rank, also runs the case on rank 0 alone and returns the relative difference
// (negative when run on one rank, where there is nothing to compare).
inline double rankAgreement(const CaseRun& run, const GlobalFields& parallel, double pScale,
                            double uScale) {
  int size = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (size == 1) return -1.0;
  double diff = 0.0;
  if (rank == 0) {
    const GlobalFields serial = run(MPI_COMM_SELF);
    diff = relativeDifference(parallel, serial, pScale, uScale);
    std::cout << "[measured] " << size << " ranks vs 1 rank: max relative difference of p, u = "
              << diff << std::endl;
  }
  MPI_Bcast(&diff, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  return diff;
}

inline bool isRoot() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank == 0;
}

inline int worldSize() {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

// Tight linear-solver tolerances so runs on different rank counts agree to 1e-10.
// A column fed from below at superficial velocity u, open at the top (p = 1e5), free-slip sides.
inline std::vector<BoundarySettings> columnBoundaries(double u) {
  return {{"zmin", BoundaryType::VelocityInlet, Vec3(0, 0, u), 0.0},
          {"zmax", BoundaryType::PressureOutlet, Vec3::Zero(), 1e5},
          {"xmin", BoundaryType::FreeSlipWall, Vec3::Zero(), 0.0},
          {"xmax", BoundaryType::FreeSlipWall, Vec3::Zero(), 0.0},
          {"ymin", BoundaryType::FreeSlipWall, Vec3::Zero(), 0.0},
          {"ymax", BoundaryType::FreeSlipWall, Vec3::Zero(), 0.0}};
}

// The strict criterion at 1e-14, so that each test's own criterion measures the discretisation. With
// PARCELFLOW_TEST_STOPPING_CRITERION=normalized (the *_normalized tests of CMakeLists.txt) the linear solves
// stop by the normalized criterion with its default tolerances instead, so that each test's own criterion
// shows what that criterion changes.
inline void tightSolvers(GasSettings& s) {
  s.solver.pressure.criterion = s.solver.momentum.criterion = StoppingCriterion::Strict;
  s.solver.pressure.relTolerance = 1e-14;
  s.solver.pressure.maxIterations = 5000;
  s.solver.momentum.relTolerance = 1e-14;
  s.solver.momentum.maxIterations = 5000;
  const char* criterion = std::getenv("PARCELFLOW_TEST_STOPPING_CRITERION");
  if (criterion && std::string(criterion) == "normalized") {
    s.solver.pressure.criterion = s.solver.momentum.criterion = StoppingCriterion::Normalized;
    static bool said = false;
    if (isRoot() && !said)
      std::cout << "[measured] linear solves stop by the normalized criterion (pressure tolerance "
                << s.solver.pressure.tolerance << ", rel_tol " << s.solver.pressure.relTol << ", final_rel_tol "
                << s.solver.pressure.finalRelTol << "; momentum tolerance " << s.solver.momentum.tolerance
                << ", rel_tol " << s.solver.momentum.relTol << ")" << std::endl;
    said = true;
  } else if (criterion) {
    ADD_FAILURE() << "PARCELFLOW_TEST_STOPPING_CRITERION=" << criterion << ": allowed is normalized";
  }
}

}  // namespace parcelflow::cfd::testing
