#include "coupling/run/geometry_stl.h"

#include <filesystem>

#include "coupling/run/broadcast_text.h"
#include "cfd/geometry/cartesian_background.hpp"
#include "cfd/base/config_error.hpp"
#include "cfd/geometry/stl_writer.hpp"
#include "cfd/geometry/surface_from_geometry.hpp"

namespace parcelflow::coupling {

std::string writeGeometryStl(const cfd::GasSettings& gas, const std::string& output_folder, MPI_Comm comm) {
  const std::string path = std::filesystem::absolute(std::filesystem::path(output_folder) / "geometry.stl").string();
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::string error;
  if (rank == 0) {
    try {
      const cfd::CartesianBackground background(gas.mesh.origin, gas.mesh.lengths, gas.mesh.cells);
      cfd::writeAsciiStl(cfd::surfaceOfGeometry(gas.geometry, background), path, "geometry");
    } catch (const cfd::ConfigError& e) {
      error = e.what();
    }
  }
  error = broadcastText(error, 0, comm);
  if (!error.empty()) throw cfd::ConfigError(error);
  return path;
}

}  // namespace parcelflow::coupling
