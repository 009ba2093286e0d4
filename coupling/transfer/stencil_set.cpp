#include "stencil_set.hpp"

namespace parcelflow::coupling {

void deposit(const StencilSet& set, int ncomp, const double* q, double* cellQ) {
  const std::size_t nc = static_cast<std::size_t>(ncomp);
  for (std::size_t p = 0; p < set.parcels(); ++p) {
    const double* qp = q + nc * p;
    for (std::size_t e = set.offset[p]; e < set.offset[p + 1]; ++e) {
      double* cq = cellQ + nc * static_cast<std::size_t>(set.cell[e]);
      const double w = set.weight[e];
      for (std::size_t m = 0; m < nc; ++m) cq[m] += w * qp[m];
    }
  }
}

void gather(const StencilSet& set, int ncomp, const double* cellQ, double* parcelQ, double orphanValue) {
  const std::size_t nc = static_cast<std::size_t>(ncomp);
  for (std::size_t p = 0; p < set.parcels(); ++p) {
    double* out = parcelQ + nc * p;
    const bool orphan = set.offset[p] == set.offset[p + 1];
    for (std::size_t m = 0; m < nc; ++m) out[m] = orphan ? orphanValue : 0.0;
    for (std::size_t e = set.offset[p]; e < set.offset[p + 1]; ++e) {
      const double* cq = cellQ + nc * static_cast<std::size_t>(set.cell[e]);
      const double w = set.weight[e];
      for (std::size_t m = 0; m < nc; ++m) out[m] += w * cq[m];
    }
  }
}

}  // namespace parcelflow::coupling
