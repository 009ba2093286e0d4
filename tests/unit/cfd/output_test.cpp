// FieldWriter: every rank writes its owned cells with parallel HDF5; check_output.py (run by ctest
// after this test) reads the files back with h5py and checks the values and the XDMF index, on a staircase
// column (npN) and on the same column with cut cells (cut_npN: the fluid fraction and the boxes drawn).
#include <gtest/gtest.h>
#include <mpi.h>
#include <sys/stat.h>

#include <cmath>
#include <string>

#include "cfd/output/field_writer.hpp"
#include "cfd/solver/gas_solver.hpp"

using namespace parcelflow::cfd;

namespace {

void writeColumn(WallRepresentation walls, const std::string& prefix) {
  int size = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const std::string dir = std::string(PARCELFLOW_CFD_OUTPUT_DIR) + "/" + prefix + "np" + std::to_string(size);
  if (rank == 0) {
    mkdir(PARCELFLOW_CFD_OUTPUT_DIR, 0755);
    mkdir(dir.c_str(), 0755);
  }
  MPI_Barrier(MPI_COMM_WORLD);

  GasSettings s;
  s.mesh.origin = Vec3(-0.06, -0.06, 0.0);
  s.mesh.lengths = Vec3(0.12, 0.12, 0.2);
  s.mesh.cells = {6, 6, 10};
  s.mesh.walls = walls;
  s.geometry = Geometry({{Geometry::Op::Union, Primitive::cylinder(0, 0, 0.05, 0, 0.2), ""}});
  s.boundaries = {{"zmin", BoundaryType::VelocityInlet, Vec3(0, 0, 0.05), 0.0},
                  {"zmax", BoundaryType::PressureOutlet, Vec3::Zero(), 1e5},
                  {"walls", BoundaryType::NoSlipWall, Vec3::Zero(), 0.0}};
  s.solver.pressure.criterion = s.solver.momentum.criterion = StoppingCriterion::Strict;
  s.solver.pressure.relTolerance = 1e-14;
  s.solver.momentum.relTolerance = 1e-14;
  GasSolver gas(s, MPI_COMM_WORLD);
  const Mesh& m = gas.mesh();
  ScalarField alpha(m.nLocalCells()), id(m.nLocalCells()), volume(m.nLocalCells());
  VectorField centre(m.nLocalCells());
  for (int c = 0; c < m.nLocalCells(); ++c) {
    const Vec3& x = m.cellCentre(c);
    alpha[c] = 1.0 - 0.3 * std::sin(20 * x[2]) * std::sin(20 * x[2]);
    id[c] = static_cast<double>(m.globalId(c));
    volume[c] = m.cellVolume(c);
    centre[c] = x;
  }
  gas.setGasFraction(alpha);
  FieldWriter writer(m, dir, "gas");
  for (int step = 1; step <= 2; ++step) {
    gas.advance(0.01);
    writer.addScalar("a_g", gas.gasFraction());
    writer.addScalar("p", gas.pressure());
    writer.addVector("u", gas.velocity());
    writer.addScalar("id_check", id);
    writer.addVector("centre_check", centre);
    writer.addScalar("volume_check", volume);
    writer.write(gas.time());
  }
}

}  // namespace

TEST(FieldWriter, WritesOwnedCellsAndXdmf) { writeColumn(WallRepresentation::Staircase, ""); }

TEST(FieldWriter, WritesCutCellsWithTheirFluidFraction) { writeColumn(WallRepresentation::CutCells, "cut_"); }
