#include "cfd/mesh/mesh.hpp"

namespace parcelflow::cfd {

int Mesh::patchId(const std::string& name) const {
  for (std::size_t p = 0; p < patchNames_.size(); ++p)
    if (patchNames_[p] == name && patchGlobalFaces_[p] > 0) return static_cast<int>(p);
  return -1;
}

double Mesh::sumOwned(const ScalarField& field) const {
  double local = 0.0;
  for (int c = 0; c < nOwned_; ++c) local += field[c];
  return sum(local);
}

double Mesh::sum(double localValue) const {
  double global = 0.0;
  MPI_Allreduce(&localValue, &global, 1, MPI_DOUBLE, MPI_SUM, comm_);
  return global;
}

double Mesh::max(double localValue) const {
  double global = 0.0;
  MPI_Allreduce(&localValue, &global, 1, MPI_DOUBLE, MPI_MAX, comm_);
  return global;
}

}  // namespace parcelflow::cfd
