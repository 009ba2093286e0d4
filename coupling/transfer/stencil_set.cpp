#include "stencil_set.hpp"

#include <type_traits>

namespace parcelflow::coupling {

namespace {

// The loops with the component count known at compile time (Width > 0), so the per-entry update is
// unrolled and vectorised; Width = 0 reads it from `ncomp` for the rare other widths.
template <int Width>
void depositLoop(const StencilSet& set, std::size_t ncomp, const double* q, double* cellQ) {
  const std::size_t nc = Width > 0 ? static_cast<std::size_t>(Width) : ncomp;
  for (std::size_t p = 0; p < set.parcels(); ++p) {
    const double* qp = q + nc * p;
    for (std::size_t e = set.offset[p]; e < set.offset[p + 1]; ++e) {
      double* cq = cellQ + nc * static_cast<std::size_t>(set.cell[e]);
      const double w = set.weight[e];
      for (std::size_t m = 0; m < nc; ++m) cq[m] += w * qp[m];
    }
  }
}

template <int Width>
void gatherLoop(const StencilSet& set, std::size_t ncomp, const double* cellQ, double* parcelQ,
                double orphanValue) {
  const std::size_t nc = Width > 0 ? static_cast<std::size_t>(Width) : ncomp;
  for (std::size_t p = 0; p < set.parcels(); ++p) {
    double* out = parcelQ + nc * p;
    const bool orphan = set.offset[p] == set.offset[p + 1];
    double local[Width > 0 ? Width : 1];  // a register-resident sum when the width is known
    double* acc = Width > 0 ? local : out;
    for (std::size_t m = 0; m < nc; ++m) acc[m] = 0.0;
    for (std::size_t e = set.offset[p]; e < set.offset[p + 1]; ++e) {
      const double* cq = cellQ + nc * static_cast<std::size_t>(set.cell[e]);
      const double w = set.weight[e];
      for (std::size_t m = 0; m < nc; ++m) acc[m] += w * cq[m];
    }
    for (std::size_t m = 0; m < nc; ++m) out[m] = orphan ? orphanValue : acc[m];
  }
}

// Calls loop.template operator()<W>() with W = ncomp for the widths the coupler uses, else W = 0.
template <class Loop>
void withWidth(int ncomp, Loop&& loop) {
  switch (ncomp) {
    case 1: return loop(std::integral_constant<int, 1>{});
    case 2: return loop(std::integral_constant<int, 2>{});
    case 4: return loop(std::integral_constant<int, 4>{});
    case 6: return loop(std::integral_constant<int, 6>{});
    default: return loop(std::integral_constant<int, 0>{});
  }
}

}  // namespace

void deposit(const StencilSet& set, int ncomp, const double* q, double* cellQ) {
  withWidth(ncomp, [&](auto width) { depositLoop<width()>(set, static_cast<std::size_t>(ncomp), q, cellQ); });
}

void gather(const StencilSet& set, int ncomp, const double* cellQ, double* parcelQ, double orphanValue) {
  withWidth(ncomp, [&](auto width) {
    gatherLoop<width()>(set, static_cast<std::size_t>(ncomp), cellQ, parcelQ, orphanValue);
  });
}

}  // namespace parcelflow::coupling
