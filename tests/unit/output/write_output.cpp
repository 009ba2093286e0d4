// Writes two snapshots of cell fields (cfd::FieldWriter, "fields") and of parcels (ParcelWriter,
// "parcels"; the second one empty) into DIR, for paraview_test.py. usage: write_output DIR
#include <mpi.h>

#include <cstdio>
#include <exception>

#include "cfd/output/field_writer.hpp"
#include "cfd/mesh/mesh_builder.hpp"
#include "coupling/output/parcel_writer.h"

using namespace parcelflow;

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, status = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  try {
    if (argc != 2) throw std::runtime_error("usage: write_output DIR");
    cfd::MeshSettings settings;
    settings.lengths = cfd::Vec3(0.04, 0.03, 0.05);
    settings.cells = {4, 3, 5};
    const cfd::Geometry box({{cfd::Geometry::Op::Union,
                              cfd::Primitive::box(cfd::Vec3::Zero(), cfd::Vec3(0.04, 0.03, 0.05)), ""}});
    const cfd::Mesh mesh = cfd::MeshBuilder::build(settings, box, MPI_COMM_WORLD);
    cfd::FieldWriter fields(mesh, argv[1], "fields");
    coupling::ParcelWriter parcels(MPI_COMM_WORLD, argv[1], "parcels");
    for (int step = 1; step <= 2; ++step) {
      cfd::ScalarField gas_fraction(mesh.nOwnedCells());
      cfd::VectorField velocity(mesh.nOwnedCells());
      for (int c = 0; c < mesh.nOwnedCells(); ++c) {
        const double id = static_cast<double>(mesh.globalId(c));
        gas_fraction[c] = 0.4 + 0.005 * id;
        velocity[c] = cfd::Vec3(step * id, 0.0, -id);
      }
      fields.addScalar("gas_fraction", gas_fraction);
      fields.addVector("gas_velocity", velocity);
      fields.write(0.1 * step);
      coupling::ParcelSnapshot local;
      for (int i = 0; step == 1 && i < 5; ++i) {
        const int id = 1000 * rank + i + 1;
        local.x.insert(local.x.end(), {0.001 * (i + 1), 0.002 * (rank + 1), 0.01 * (i + 1)});
        local.v.insert(local.v.end(), {0.0, 0.0, -0.1 * id});
        local.dp.push_back(1e-3 * (1 + i % 2));
        local.np.push_back(8.0);
        local.type.push_back(1 + i % 2);
        local.id.push_back(id);
      }
      parcels.write(0.1 * step, local);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "write_output: %s\n", e.what());
    status = 1;
  }
  MPI_Finalize();
  return status;
}
