// The gas part of a checkpoint (cfd/output/gas_checkpoint.hpp): a solver restored from the file has exactly the
// state of the one that wrote it, and the next step of both is the same to the last bit (the writer builds
// a new pressure preconditioner too, as the coupled loop makes it); a file of another checkpoint is refused
// naming checkpoint_id. On 1, 2 and 3 ranks, on a box (boundary faces are found by their cell and centre: its
// corner cells have two and three) and on a pipe of cut cells whose merged cells have two faces to one
// neighbour and whose walls face 45 degrees between two axes.
#include <gtest/gtest.h>
#include <mpi.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cfd/base/config_error.hpp"
#include "cfd/output/gas_checkpoint.hpp"
#include "cfd/solver/gas_config.hpp"

using namespace parcelflow::cfd;

namespace {

const char* const kCase = R"(
mesh: {lengths: [0.06, 0.04, 0.12], cells: [6, 4, 12]}
gas: {density: 1.2, viscosity: 1.8e-5, gravity: [0, 0, -9.81]}
boundaries: {zmin: {type: velocity_inlet, superficial_velocity: [0, 0, 0.5]}, zmax: {type: pressure_outlet},
             xmin: {type: wall}, xmax: {type: wall}, ymin: {type: wall}, ymax: {type: wall}}
)";

// The cut-cell pipe of the mesh tests: R 0.5 m + 5e-11 m on 24 x 24 x 2 cells, slivers merged.
const char* const kCutPipe = R"(
mesh: {origin: [-0.6, -0.6, 0.0], lengths: [1.2, 1.2, 0.1], cells: [24, 24, 2], walls: cut_cells}
geometry: [{shape: {cylinder: {center: [0, 0], radius: 0.50000000005, zmin: 0.0, zmax: 0.1}}}]
gas: {density: 1.2, viscosity: 1.8e-5, gravity: [0, 0, -9.81]}
boundaries: {zmin: {type: velocity_inlet, superficial_velocity: [0, 0, 0.5]}, zmax: {type: pressure_outlet},
             walls: {type: wall}}
)";

// A bed-like gas fraction and drag that change with time, so that every stored level matters.
void setCoupling(GasSolver& gas, double t) {
  const Mesh& m = gas.mesh();
  ScalarField alpha(m.nOwnedCells()), beta(m.nOwnedCells());
  VectorField betaUs(m.nOwnedCells(), Vec3::Zero());
  for (int c = 0; c < m.nOwnedCells(); ++c) {
    const Vec3& x = m.cellCentre(c);
    alpha[c] = x[2] < 0.05 ? 0.5 + 0.1 * std::sin(80.0 * x[0] + 40.0 * t) : 1.0;
    beta[c] = x[2] < 0.05 ? 2e3 : 0.0;
    betaUs[c] = Vec3(0.0, 0.0, 0.01 * beta[c]);
  }
  gas.setGasFraction(alpha);
  gas.setDragCoefficient(beta);
  gas.setDragSource(betaUs);
}

// A temporary file of rank 0's, its name on every rank; removed when the test ends, also by a failure that
// throws (every rank leaves the test together: the checkpoint calls are collective).
class SharedTempFile {
 public:
  SharedTempFile() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    char path[] = "/tmp/pf_gas_checkpoint_XXXXXX";
    if (rank_ == 0) {
      const int fd = mkstemp(path);
      close(fd);
    }
    MPI_Bcast(path, sizeof path, MPI_CHAR, 0, MPI_COMM_WORLD);
    path_ = path;
  }
  ~SharedTempFile() {
    MPI_Barrier(MPI_COMM_WORLD);
    if (rank_ == 0) std::remove(path_.c_str());
  }
  const std::string& path() const { return path_; }

 private:
  int rank_ = 0;
  std::string path_;
};

template <class Field>
void expectSame(const Field& a, const Field& b, std::size_t n, const char* what) {
  for (std::size_t i = 0; i < n; ++i) ASSERT_TRUE(a[i] == b[i]) << what << " differs at " << i;
}

}  // namespace

class GasCheckpoint : public ::testing::TestWithParam<const char*> {};

TEST_P(GasCheckpoint, RestoredSolverContinuesBitForBit) {
  const GasSettings settings = GasConfig(YAML::Load(GetParam())).settings();
  const double dt = 2e-3;
  GasSolver writer(settings, MPI_COMM_WORLD);
  for (int step = 0; step < 5; ++step) {
    setCoupling(writer, step * dt);
    writer.advance(dt);
  }
  if (settings.mesh.walls == WallRepresentation::CutCells) {
    ASSERT_GT(writer.mesh().mergedCells(), 0);
  }
  const SharedTempFile file;
  const std::string& path = file.path();
  writeGasCheckpoint(writer, path, "5-test");
  writer.rebuildPreconditionerNextStep();

  GasSolver reader(settings, MPI_COMM_WORLD);
  readGasCheckpoint(reader, path, "5-test");
  const GasSolver::State a = writer.state(), b = reader.state();
  const std::size_t n = writer.mesh().nOwnedCells();
  expectSame(a.alpha, b.alpha, n, "alpha");
  expectSame(a.pRgh, b.pRgh, n, "p_rgh");
  expectSame(a.gradPRgh, b.gradPRgh, n, "grad p_rgh");
  expectSame(a.velocity, b.velocity, n, "velocity");
  expectSame(a.phi, b.phi, a.phi.size(), "phi");
  expectSame(a.phiBoundary, b.phiBoundary, a.phiBoundary.size(), "phi_b");
  EXPECT_EQ(a.time, b.time);
  expectSame(writer.pressure(), reader.pressure(), writer.mesh().nLocalCells(), "p (ghosts too)");

  for (int step = 5; step < 8; ++step) {
    setCoupling(writer, step * dt);
    setCoupling(reader, step * dt);
    const StepReport ra = writer.advance(dt), rb = reader.advance(dt);
    EXPECT_EQ(ra.pressureIterations, rb.pressureIterations);
  }
  expectSame(writer.velocity(), reader.velocity(), writer.mesh().nLocalCells(), "velocity after 3 steps");
  expectSame(writer.pressure(), reader.pressure(), writer.mesh().nLocalCells(), "pressure after 3 steps");

  try {
    readGasCheckpoint(reader, path, "7-other");
    ADD_FAILURE() << "a file of another checkpoint was accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("checkpoint_id"), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Meshes, GasCheckpoint, ::testing::Values(kCase, kCutPipe));
