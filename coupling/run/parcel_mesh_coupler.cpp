#include "coupling/run/parcel_mesh_coupler.h"

#include <mpi.h>

#include <cmath>
#include <limits>
#include <variant>

#include "cfd/base/internal_error.hpp"

namespace parcelflow::coupling {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

ParcelMeshCoupler::ParcelMeshCoupler(const BackgroundGrid& grid, const CellOwnerMap& owners, TransferKernel kernel,
                                     DragLaw drag, DragLimits limits, GasProperties gas)
    : grid_(grid),
      exchange_(owners),
      kernel_(std::move(kernel)),
      drag_(std::move(drag)),
      limits_(limits),
      gas_(gas),
      uses_mean_diameter_(usesMeanDiameter(drag_)),
      kernel_reads_diameters_(std::visit([](const auto& k) { return k.readsDiameter(); }, kernel_)),
      fluid_(grid, [&](int i, int j, int k) { return owners.fluidFraction(backgroundCell(i, j, k)); }) {
  grid_.validate();
  int rank = 0;
  MPI_Comm_rank(owners.comm(), &rank);
  // An owned gas cell's fluid volume: the shares of the background cells it is made of.
  const double box_volume = grid.spacing[0] * grid.spacing[1] * grid.spacing[2];
  for (long c = 0; c < owners.backgroundSize(); ++c) {
    if (owners.ownerRank(c) != rank) continue;
    const std::size_t owned = static_cast<std::size_t>(owners.ownerIndex(c));
    if (owned >= owned_volume_.size()) owned_volume_.resize(owned + 1, 0.0);
    owned_volume_[owned] += owners.fluidFraction(c) * box_volume;
  }
  n_owned_ = static_cast<int>(owned_volume_.size());
  for (double v : owned_volume_) PARCELFLOW_ASSERT(v > 0.0, "ParcelMeshCoupler: an owned cell has no background cell");
}

TransferStats ParcelMeshCoupler::beginStep(const ParcelBatch& parcels) {
  parcels_ = parcels;
  if (kernel_reads_diameters_) {
    // collision diameter D = dp np^(1/3) in both parcel modes (constant np, and constant D with np = (D/dp)^3)
    diameters_.resize(parcels.size);
    for (std::size_t p = 0; p < parcels.size; ++p) diameters_[p] = parcels.dp[p] * std::cbrt(parcels.np[p]);
  }
  const TransferStats stats = buildBoxStencils(kernel_, grid_, fluid_, parcels.size, parcels.x, stencils_,
                                               kernel_reads_diameters_ ? diameters_.data() : nullptr);
  // Every fluid cell of the box is exchanged (cells no window reaches carry zeros): the box is this
  // rank's parcels' neighbourhood, so it is about the cells the stencils touch.
  touched_.clear();
  box_of_touched_.clear();
  touched_fraction_.clear();
  const auto& lo = stencils_.lo;
  for (int k = lo[2]; k < lo[2] + stencils_.cells[2]; ++k)
    for (int j = lo[1]; j < lo[1] + stencils_.cells[1]; ++j)
      for (int i = lo[0]; i < lo[0] + stencils_.cells[0]; ++i)
        if (fluid_.isFluid(i, j, k)) {
          touched_.push_back(backgroundCell(i, j, k));
          box_of_touched_.push_back(stencils_.boxIndex(i, j, k));
          touched_fraction_.push_back(fluid_.fluidFraction(i, j, k));
        }
  exchange_.setCells(touched_);
  return stats;
}

void ParcelMeshCoupler::depositToOwners(const std::vector<double>& per_parcel, int width,
                                        std::vector<double>& owned) {
  depositWith(stencils_, false, per_parcel, width, owned);
}

void ParcelMeshCoupler::depositSquaredWeightsToOwners(const std::vector<double>& per_parcel, int width,
                                                      std::vector<double>& owned) {
  // separable weights: squaring each axis' factors (the z factors carry the renormalisation) squares w
  squared_stencils_ = stencils_;
  for (Window& w : squared_stencils_.windows)
    for (int axis = 0; axis < 3; ++axis)
      for (int a = 0; a < w.n[axis]; ++a) w.f[axis][a] *= w.f[axis][a];
  depositWith(squared_stencils_, true, per_parcel, width, owned);
}

void ParcelMeshCoupler::depositWith(const BoxStencils& stencils, bool squared,
                                    const std::vector<double>& per_parcel, int width, std::vector<double>& owned) {
  std::vector<double>& on_box = scratch_.on_box;
  on_box.assign(static_cast<std::size_t>(stencils.boxSize()) * width, 0.0);
  deposit(stencils, width, per_parcel.data(), on_box.data());
  std::vector<double>& on_touched = scratch_.on_touched;
  on_touched.resize(touched_.size() * width);
  // a cell cut by a wall takes its fluid share of what the window put on the whole cell (its weight w f)
  for (std::size_t t = 0; t < touched_.size(); ++t) {
    const double share = squared ? touched_fraction_[t] * touched_fraction_[t] : touched_fraction_[t];
    for (int m = 0; m < width; ++m) on_touched[width * t + m] = share * on_box[width * box_of_touched_[t] + m];
  }
  owned.assign(static_cast<std::size_t>(n_owned_) * width, 0.0);
  exchange_.sumToOwners(on_touched, width, owned);
}

void ParcelMeshCoupler::gatherFromOwned(const std::vector<double>& owned, int width, double orphan_value,
                                        std::vector<double>& at_parcels) {
  std::vector<double>& on_touched = scratch_.on_touched;
  exchange_.fetchFromOwners(owned, width, on_touched);
  // Non-fluid box cells stay 0: windows reach them with weights that must contribute nothing.
  std::vector<double>& on_box = scratch_.on_box;
  on_box.assign(static_cast<std::size_t>(stencils_.boxSize()) * width, 0.0);
  for (std::size_t t = 0; t < touched_.size(); ++t)
    for (int m = 0; m < width; ++m)
      on_box[width * box_of_touched_[t] + m] = touched_fraction_[t] * on_touched[width * t + m];
  at_parcels.resize(parcels_.size * width);
  gather(stencils_, width, on_box.data(), at_parcels.data(), orphan_value);
}

void ParcelMeshCoupler::depositSolids(std::vector<double>& owned_solid_fraction) {
  const int width = uses_mean_diameter_ ? 2 : 1;
  std::vector<double>& moments = scratch_.per_parcel;
  moments.resize(parcels_.size * width);
  for (std::size_t p = 0; p < parcels_.size; ++p) {
    const double d = parcels_.dp[p];
    moments[width * p] = parcels_.np[p] * kPi / 6.0 * d * d * d;
    if (uses_mean_diameter_) moments[width * p + 1] = parcels_.np[p] * d * d;
  }
  depositToOwners(moments, width, owned_moments_);
  owned_solid_fraction.resize(n_owned_);
  for (int c = 0; c < n_owned_; ++c) owned_solid_fraction[c] = owned_moments_[width * c] / owned_volume_[c];
}

DragStats ParcelMeshCoupler::computeDrag(const std::vector<double>& owned_gas_fraction,
                                         const std::vector<double>& owned_velocity, SolidsOnCells& solids,
                                         GasAtParcels& at_parcels) {
  const std::size_t n = parcels_.size;
  // a_g, u and, for BVK, the two moments of depositSolids.
  const int width = uses_mean_diameter_ ? 6 : 4;
  PARCELFLOW_ASSERT(!uses_mean_diameter_ || owned_moments_.size() == 2 * static_cast<std::size_t>(n_owned_),
                        "computeDrag needs this step's depositSolids for the Sauter mean");
  std::vector<double>& owned = scratch_.owned;
  owned.resize(static_cast<std::size_t>(n_owned_) * width);
  for (int c = 0; c < n_owned_; ++c) {
    owned[width * c] = owned_gas_fraction[c];
    for (int d = 0; d < 3; ++d) owned[width * c + 1 + d] = owned_velocity[3 * c + d];
    if (uses_mean_diameter_)
      for (int m = 0; m < 2; ++m) owned[width * c + 4 + m] = owned_moments_[2 * c + m];
  }
  // Orphans get NaN: the drag law counts them as invalid input and gives them kappa = 0.
  std::vector<double>& gas = scratch_.gathered;
  gatherFromOwned(owned, width, std::numeric_limits<double>::quiet_NaN(), gas);
  at_parcels.gas_fraction.resize(n);
  at_parcels.mean_diameter.resize(uses_mean_diameter_ ? n : 0);
  std::vector<double>& slip = scratch_.slip;
  slip.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    const double* g = gas.data() + width * p;
    at_parcels.gas_fraction[p] = g[0];
    double s2 = 0.0;
    for (int d = 0; d < 3; ++d) s2 += std::pow(g[1 + d] - parcels_.v[3 * p + d], 2);
    slip[p] = std::sqrt(s2);
    // <d> = sum np dp^3 / sum np dp^2 = (6/pi) sum np V_p / sum np dp^2 (NaN for orphans: invalid input)
    if (uses_mean_diameter_) at_parcels.mean_diameter[p] = 6.0 / kPi * g[4] / g[5];
  }
  ParcelDragBatch batch;
  batch.size = n;
  batch.alphaG = at_parcels.gas_fraction.data();
  batch.slip = slip.data();
  batch.dp = parcels_.dp;
  batch.np = parcels_.np;
  batch.dMean = uses_mean_diameter_ ? at_parcels.mean_diameter.data() : nullptr;
  batch.rhoG = gas_.density;
  batch.muG = gas_.viscosity;
  at_parcels.kappa.assign(n, 0.0);
  std::vector<double>& momentum = scratch_.per_parcel;
  momentum.resize(4 * n);
  const DragStats stats = forEachParcel(drag_, batch, limits_, [&](std::size_t p, double, double kappa) {
    at_parcels.kappa[p] = kappa;
    momentum[4 * p] = kappa;
    for (int d = 0; d < 3; ++d) momentum[4 * p + 1 + d] = kappa * parcels_.v[3 * p + d];
  });
  std::vector<double>& deposited = scratch_.deposited;
  depositToOwners(momentum, 4, deposited);
  solids.beta.resize(n_owned_);
  solids.beta_us.resize(3 * static_cast<std::size_t>(n_owned_));
  for (int c = 0; c < n_owned_; ++c) {
    solids.beta[c] = deposited[4 * c] / owned_volume_[c];
    for (int d = 0; d < 3; ++d) solids.beta_us[3 * c + d] = deposited[4 * c + 1 + d] / owned_volume_[c];
  }
  return stats;
}

void ParcelMeshCoupler::gatherGas(const std::vector<double>& owned_velocity, const std::vector<double>& owned_grad_p,
                                  GasAtParcels& at_parcels) {
  std::vector<double>& owned = scratch_.owned;
  owned.resize(static_cast<std::size_t>(n_owned_) * 6);
  for (int c = 0; c < n_owned_; ++c)
    for (int d = 0; d < 3; ++d) {
      owned[6 * c + d] = owned_velocity[3 * c + d];
      owned[6 * c + 3 + d] = owned_grad_p[3 * c + d];
    }
  // Orphans (counted in beginStep) feel no gas: zero velocity and pressure gradient, kappa 0.
  std::vector<double>& gas = scratch_.gathered;
  gatherFromOwned(owned, 6, 0.0, gas);
  at_parcels.gas_velocity.resize(3 * parcels_.size);
  at_parcels.grad_p.resize(3 * parcels_.size);
  for (std::size_t p = 0; p < parcels_.size; ++p)
    for (int d = 0; d < 3; ++d) {
      at_parcels.gas_velocity[3 * p + d] = gas[6 * p + d];
      at_parcels.grad_p[3 * p + d] = gas[6 * p + 3 + d];
    }
}

}  // namespace parcelflow::coupling
