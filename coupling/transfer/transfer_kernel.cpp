#include "coupling/transfer/transfer_kernel.hpp"

#include <stdexcept>

#include "cfd/base/config_error.hpp"

namespace parcelflow::coupling {

std::vector<std::string> transferKernelNames() { return {GaussianKernel::typeName, CentroidKernel::typeName}; }

TransferKernel makeTransferKernel(const std::string& name, const TransferKernelOptions& options) {
  if (name == GaussianKernel::typeName)
    return GaussianKernel(options.gaussianSharpness, options.gaussianRadius, options.gaussianSpacing,
                          options.gaussianIsotropic, options.gaussianParcelFactor,
                          options.gaussianReflectAtWalls);
  if (name == CentroidKernel::typeName) return CentroidKernel(options.centroidSearchRadius);
  std::string valid;
  for (const std::string& n : transferKernelNames()) valid += (valid.empty() ? "" : ", ") + n;
  throw cfd::ConfigError("coupling.kernel.type", name, "one of " + valid);
}

std::string transferKernelName(const TransferKernel& kernel) {
  return std::visit([](const auto& k) { return std::string(k.typeName); }, kernel);
}

}  // namespace parcelflow::coupling
