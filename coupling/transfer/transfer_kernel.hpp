#pragma once
// Run-time selection of the particle <-> mesh kernel by name ("gaussian", "centroid"). A
// TransferKernel holds one concrete kernel; buildBoxStencils visits it once per batch and runs a loop
// templated on the concrete kernel (no virtual call per parcel). Unknown names throw
// cfd::ConfigError listing the valid ones.
#include <string>
#include <variant>
#include <vector>

#include "coupling/transfer/centroid_kernel.hpp"
#include "coupling/transfer/gaussian_kernel.hpp"

namespace parcelflow::coupling {

using TransferKernel = std::variant<GaussianKernel, CentroidKernel>;

struct TransferKernelOptions {
  double gaussianSharpness = 1.0;  // a in exp(-a |dx|^2 / h^2)
  int gaussianRadius = 2;          // stencil +-R cells per axis
  // h = the cube root of the cell volume (cells of gaussianSpacing) instead of the cell length per axis
  bool gaussianIsotropic = true;
  double gaussianSpacing[3] = {1.0, 1.0, 1.0};
  // lambda: a parcel of collision diameter D is spread over at least h_p = lambda D (0: the cell's h only)
  double gaussianParcelFactor = 0.0;
  // walls (the background box's faces and cells without fluid) mirror the kernel (image parcels) instead of truncating it
  bool gaussianReflectAtWalls = false;
  int centroidSearchRadius = 1;    // fallback search for the centroid kernel
};

std::vector<std::string> transferKernelNames();
TransferKernel makeTransferKernel(const std::string& name, const TransferKernelOptions& options = {});
std::string transferKernelName(const TransferKernel& kernel);

}  // namespace parcelflow::coupling
