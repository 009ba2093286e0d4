#pragma once
// Per-parcel drag over a batch of parcels: the law is chosen once (one std::visit per batch), the loop
// body is templated on the concrete law, so there is no virtual/indirect call per parcel.
//
// Limits, never silent: a_g below DragLimits::alphaGFloor is evaluated at the floor, a_g above 1 at 1,
// and both are counted in DragStats; non-finite or non-physical inputs give K = kappa = 0 and are
// counted as invalidInput; a law's own bound on a correction is counted as filterCorrectionClamped.
// The caller reports the counts (DESIGN.md section 4).
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "coupling/drag/drag_law.hpp"

namespace parcelflow::coupling {

struct DragLimits {
  double alphaGFloor = 0.0;  // the named config value (a_g floor); must lie in (0, 1)
};

struct ParcelDragBatch {
  std::size_t size = 0;
  const double* alphaG = nullptr;  // gas fraction gathered at each parcel
  const double* slip = nullptr;    // |u_gathered - v| at each parcel
  const double* dp = nullptr;      // real particle diameter
  const double* np = nullptr;      // real particles per parcel
  const double* dMean = nullptr;   // optional local Sauter-mean diameter (BVK polydisperse); may be null
  double rhoG = 0.0;
  double muG = 0.0;
};

struct DragStats {
  std::size_t parcels = 0;
  std::size_t alphaGFloored = 0;   // a_g < floor: evaluated at the floor
  std::size_t alphaGAboveOne = 0;  // a_g > 1: evaluated at 1
  std::size_t invalidInput = 0;    // non-finite a_g/slip, slip < 0, dp <= 0 or np <= 0: K = kappa = 0
  std::size_t filterCorrectionClamped = 0;  // a filtered law bounded its correction (RadlSundaresan: H = 0)
  double minAlphaG = std::numeric_limits<double>::infinity();  // before flooring

  void merge(const DragStats& o) {
    parcels += o.parcels;
    alphaGFloored += o.alphaGFloored;
    alphaGAboveOne += o.alphaGAboveOne;
    invalidInput += o.invalidInput;
    filterCorrectionClamped += o.filterCorrectionClamped;
    if (o.minAlphaG < minAlphaG) minAlphaG = o.minAlphaG;
  }
};

namespace drag_detail {
void checkBatch(const ParcelDragBatch& batch, const DragLimits& limits);  // PARCELFLOW_ASSERT

template <class Law, class = void>
struct ReportsClamp : std::false_type {};
template <class Law>
struct ReportsClamp<Law, std::void_t<decltype(std::declval<const Law&>().coefficient(
                             std::declval<const DragInput&>(), std::declval<bool&>()))>> : std::true_type {};

// K of one parcel; a law that bounds a correction says so and it is counted.
template <class Law>
double coefficientCounted(const Law& law, const DragInput& in, DragStats& stats) noexcept {
  if constexpr (ReportsClamp<Law>::value) {
    bool clamped = false;
    const double k = law.coefficient(in, clamped);
    if (clamped) ++stats.filterCorrectionClamped;
    return k;
  } else {
    return law.coefficient(in);
  }
}
}  // namespace drag_detail

// Calls fn(p, K, kappa) for every parcel p, K = beta / a_s [kg/(m^3 s)], kappa = np V_p K [kg/s].
template <class Fn>
DragStats forEachParcel(const DragLaw& law, const ParcelDragBatch& batch, const DragLimits& limits,
                        Fn&& fn) {
  drag_detail::checkBatch(batch, limits);
  return visitDragLaw(law, [&](const auto& concreteLaw) {
    DragStats stats;
    stats.parcels = batch.size;
    DragInput in;
    in.rhoG = batch.rhoG;
    in.muG = batch.muG;
    for (std::size_t p = 0; p < batch.size; ++p) {
      const double a = batch.alphaG[p];
      in.slip = batch.slip[p];
      in.dp = batch.dp[p];
      in.dMean = batch.dMean ? batch.dMean[p] : 0.0;
      const double np = batch.np[p];
      if (!std::isfinite(a) || !std::isfinite(in.slip) || !(in.slip >= 0.0) || !(in.dp > 0.0) ||
          !(np > 0.0) || !std::isfinite(in.dMean)) {
        ++stats.invalidInput;
        fn(p, 0.0, 0.0);
        continue;
      }
      if (a < stats.minAlphaG) stats.minAlphaG = a;
      if (a < limits.alphaGFloor) {
        ++stats.alphaGFloored;
        in.alphaG = limits.alphaGFloor;
      } else if (a > 1.0) {
        ++stats.alphaGAboveOne;
        in.alphaG = 1.0;
      } else {
        in.alphaG = a;
      }
      const double k = drag_detail::coefficientCounted(concreteLaw, in, stats);
      fn(p, k, parcelKappa(np, in.dp, k));
    }
    return stats;
  });
}

// kappa[p] = np V_p beta / a_s for every parcel of the batch.
DragStats computeParcelKappa(const DragLaw& law, const ParcelDragBatch& batch, const DragLimits& limits,
                             double* kappa);

}  // namespace parcelflow::coupling
