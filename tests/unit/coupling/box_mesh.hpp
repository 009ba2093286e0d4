#pragma once
// The 3 x 2 x 5 box of 0.1 m cells of the coupling unit tests (whole cells, patches xmin ... zmax), on every
// rank of MPI_COMM_WORLD.
#include <mpi.h>

#include "cfd/mesh/mesh_builder.hpp"

namespace parcelflow::coupling::test {

inline cfd::Mesh boxMesh() {
  cfd::MeshSettings s;
  s.lengths = cfd::Vec3(0.3, 0.2, 0.5);
  s.cells = {3, 2, 5};
  return cfd::MeshBuilder::build(s, cfd::Geometry(), MPI_COMM_WORLD);
}

}  // namespace parcelflow::coupling::test
