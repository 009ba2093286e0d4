#include "coupling/run/parcel_heat_exchange.hpp"

#include <cmath>
#include <limits>
#include <utility>

#include "cfd/base/internal_error.hpp"

namespace parcelflow::coupling {

ParcelHeatExchange::ParcelHeatExchange(NusseltCorrelation correlation, HeatLimits limits, GasThermalProperties gas)
    : correlation_(std::move(correlation)), limits_(limits), gas_(gas) {}

HeatStats ParcelHeatExchange::depositExchange(ParcelMeshCoupler& coupler, const GasAtParcels& at_parcels,
                                              const double* temperature, const double* heat_capacity, double dt,
                                              std::vector<double>& coeff, std::vector<double>& source) {
  const ParcelBatch& parcels = coupler.parcels();
  const std::size_t n = parcels.size;
  PARCELFLOW_ASSERT(at_parcels.gas_fraction.size() == n && at_parcels.gas_velocity.size() == 3 * n,
                    "heat exchange: call after this step's computeDrag and gatherGas");
  PARCELFLOW_ASSERT(dt > 0.0, "heat exchange: the coupling interval must be positive");
  slip_.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    double s2 = 0.0;
    for (int d = 0; d < 3; ++d) s2 += std::pow(at_parcels.gas_velocity[3 * p + d] - parcels.v[3 * p + d], 2);
    slip_[p] = std::sqrt(s2);
  }
  ParcelHeatBatch batch;
  batch.size = n;
  batch.alphaG = at_parcels.gas_fraction.data();
  batch.slip = slip_.data();
  batch.dp = parcels.dp;
  batch.np = parcels.np;
  batch.gas = gas_;
  effective_.assign(n, 0.0);
  temperature_.assign(temperature, temperature + n);
  deposit_.resize(2 * n);
  const HeatStats stats = forEachParcelHeat(correlation_, batch, limits_, [&](std::size_t p, double, double h) {
    const double mc = heat_capacity[p];
    effective_[p] = mc > 0.0 ? h * mc / (mc + dt * h) : 0.0;
    deposit_[2 * p] = effective_[p];
    deposit_[2 * p + 1] = effective_[p] * temperature[p];
  });
  std::vector<double> owned;
  coupler.depositToOwners(deposit_, 2, owned);
  const int cells = coupler.ownedCells();
  coeff.resize(cells);
  source.resize(cells);
  for (int c = 0; c < cells; ++c) {
    coeff[c] = owned[2 * c];
    source[c] = owned[2 * c + 1];
  }
  return stats;
}

long ParcelHeatExchange::gatherTemperature(ParcelMeshCoupler& coupler, const std::vector<double>& owned_temperature,
                                           std::vector<double>& gas_temperature, std::vector<double>& held_source) {
  const std::size_t n = coupler.parcels().size;
  PARCELFLOW_ASSERT(effective_.size() == n, "heat exchange: gatherTemperature without this step's depositExchange");
  coupler.gatherFromOwned(owned_temperature, 1, std::numeric_limits<double>::quiet_NaN(), gas_temperature);
  held_source.resize(n);
  long orphans = 0;
  for (std::size_t p = 0; p < n; ++p) {
    if (std::isnan(gas_temperature[p])) {
      ++orphans;
      held_source[p] = 0.0;
      continue;
    }
    held_source[p] = effective_[p] * (gas_temperature[p] - temperature_[p]);
  }
  return orphans;
}

}  // namespace parcelflow::coupling
