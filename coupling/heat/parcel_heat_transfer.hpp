#pragma once
// Per-parcel gas-particle conductance over a batch of parcels: the correlation is chosen once (one
// std::visit per batch) and the loop body is templated on it, so there is no indirect call per parcel.
//
//   H = np h pi d_p^2,  h = Nu k_g / d_p   [W/K]: each of the np real particles has its own surface, so
//   a parcel's thermal response time M c_p / H is its particles' (M = np m_p).
//
// Limits, never silent (the same as the drag's): a_g below HeatLimits::alphaGFloor is evaluated at the
// floor, a_g above 1 at 1, both counted; non-finite or non-physical inputs give H = 0 and are counted as
// invalidInput; a parcel outside the correlation's stated range (a_g below its minimum or Re above its
// maximum) is evaluated all the same and counted as outsideRange. The caller reports the counts.
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "coupling/heat/nusselt_correlation.hpp"

namespace parcelflow::coupling {

struct HeatLimits {
  double alphaGFloor = 0.0;  // the named config value (a_g floor, the drag's); must lie in (0, 1)
};

struct GasThermalProperties {
  double rho = 0.0;           // density [kg/m^3]
  double mu = 0.0;            // dynamic viscosity [Pa s]
  double conductivity = 0.0;  // k_g [W/(m K)]
  double heatCapacity = 0.0;  // c_g [J/(kg K)]
};

struct ParcelHeatBatch {
  std::size_t size = 0;
  const double* alphaG = nullptr;  // gas fraction gathered at each parcel
  const double* slip = nullptr;    // |u_gathered - v| at each parcel
  const double* dp = nullptr;      // real particle diameter
  const double* np = nullptr;      // real particles per parcel
  GasThermalProperties gas;
};

struct HeatStats {
  std::size_t parcels = 0;
  std::size_t alphaGFloored = 0;   // a_g < floor: evaluated at the floor
  std::size_t alphaGAboveOne = 0;  // a_g > 1: evaluated at 1
  std::size_t invalidInput = 0;    // non-finite a_g/slip, slip < 0, dp <= 0 or np <= 0: H = 0
  std::size_t outsideRange = 0;    // outside the correlation's stated a_g or Re range (evaluated)
  double maxReynolds = 0.0;

  void merge(const HeatStats& o) {
    parcels += o.parcels;
    alphaGFloored += o.alphaGFloored;
    alphaGAboveOne += o.alphaGAboveOne;
    invalidInput += o.invalidInput;
    outsideRange += o.outsideRange;
    if (o.maxReynolds > maxReynolds) maxReynolds = o.maxReynolds;
  }
};

namespace heat_detail {
void checkBatch(const ParcelHeatBatch& batch, const HeatLimits& limits);  // PARCELFLOW_ASSERT
constexpr double kPi = 3.14159265358979323846;
}  // namespace heat_detail

// Conductance of one parcel from its Nusselt number: np (Nu k_g / d_p) pi d_p^2 = np Nu k_g pi d_p.
inline double parcelConductance(double np, double dp, double nusselt, double conductivity) noexcept {
  return np * nusselt * conductivity * heat_detail::kPi * dp;
}

// Calls fn(p, Nu, H) for every parcel p of the batch.
template <class Fn>
HeatStats forEachParcelHeat(const NusseltCorrelation& correlation, const ParcelHeatBatch& batch,
                            const HeatLimits& limits, Fn&& fn) {
  heat_detail::checkBatch(batch, limits);
  return visitNusseltCorrelation(correlation, [&](const auto& concrete) {
    using Correlation = std::decay_t<decltype(concrete)>;
    HeatStats stats;
    stats.parcels = batch.size;
    NusseltInput in;
    const GasThermalProperties& gas = batch.gas;
    in.prandtl = gas.heatCapacity * gas.mu / gas.conductivity;
    for (std::size_t p = 0; p < batch.size; ++p) {
      const double a = batch.alphaG[p], slip = batch.slip[p], dp = batch.dp[p], np = batch.np[p];
      if (!std::isfinite(a) || !std::isfinite(slip) || !(slip >= 0.0) || !(dp > 0.0) || !(np > 0.0) ||
          !std::isfinite(dp) || !std::isfinite(np)) {
        ++stats.invalidInput;
        fn(p, 0.0, 0.0);
        continue;
      }
      if (a < limits.alphaGFloor) {
        ++stats.alphaGFloored;
        in.alphaG = limits.alphaGFloor;
      } else if (a > 1.0) {
        ++stats.alphaGAboveOne;
        in.alphaG = 1.0;
      } else {
        in.alphaG = a;
      }
      in.reynolds = particleReynolds(in.alphaG, gas.rho, slip, dp, gas.mu);
      if (in.reynolds > stats.maxReynolds) stats.maxReynolds = in.reynolds;
      if (in.alphaG < Correlation::minAlphaG || in.reynolds > Correlation::maxReynolds) ++stats.outsideRange;
      const double nu = concrete.nusselt(in);
      fn(p, nu, parcelConductance(np, dp, nu, gas.conductivity));
    }
    return stats;
  });
}

// conductance[p] = H of every parcel of the batch [W/K].
HeatStats computeParcelConductance(const NusseltCorrelation& correlation, const ParcelHeatBatch& batch,
                                   const HeatLimits& limits, double* conductance);

}  // namespace parcelflow::coupling
