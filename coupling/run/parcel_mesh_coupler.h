// Particle <-> mesh transfer of one coupling step across MPI ranks (DESIGN sections 4 and 7).
//
// Parcels live where LIGGGHTS' decomposition puts them, gas cells where METIS puts them. Each rank
// deposits on the box of background cells its parcels' kernel windows span, and CellExchange sums the
// box's fluid cells into the owning ranks (and fetches owned gas values back over the same pattern). Weights
// are renormalised over all fluid cells of the stencil (a cell is fluid if it has an owner anywhere), each
// counted with its fluid share where a wall cuts it, so deposited volume and momentum are conserved exactly,
// at walls, in cut and merged cells and across ranks; a solids fraction is over the gas cell's fluid volume.
//
// One step: beginStep(parcels) -> depositSolids -> computeDrag -> (gas advances) -> gatherGas.
// beginStep computes every parcel's stencil once (box_stencils.hpp: separable windows on the box of
// background cells around this rank's parcels); all transfers of the step reuse it, so the weights are
// the same both ways. The box's fluid cells are the cells exchanged with their owners.
#pragma once

#include <vector>

#include "coupling/transfer/background_grid.hpp"
#include "coupling/transfer/box_stencils.hpp"
#include "coupling/exchange/cell_exchange.h"
#include "coupling/drag/parcel_drag.hpp"
#include "coupling/transfer/stencil.hpp"
#include "coupling/transfer/transfer_kernel.hpp"

namespace parcelflow::coupling {

// The local parcels of this rank; vectors interleaved xyz (x[3p + d]).
struct ParcelBatch {
  std::size_t size = 0;
  const double* x = nullptr;
  const double* v = nullptr;
  const double* dp = nullptr;  // real particle diameter
  const double* np = nullptr;  // real particles per parcel
  const double* mass = nullptr;  // parcel mass (read by coupling.class_collisions only)
  const int* type = nullptr;     // LIGGGHTS atom type, 1-based (likewise)
};

struct GasProperties {
  double density = 1.2;
  double viscosity = 1.8e-5;
};

// What the gas solver needs from the parcels, per owned cell.
struct SolidsOnCells {
  std::vector<double> solid_fraction;  // a_s (not floored)
  std::vector<double> beta;            // sum of w kappa / V_cell   [kg/(m^3 s)]
  std::vector<double> beta_us;         // sum of w kappa v / V_cell, interleaved xyz
};

// What the parcels need from the gas, per parcel (interleaved xyz where 3 components).
struct GasAtParcels {
  std::vector<double> kappa;        // implicit drag coefficient [kg/s]
  std::vector<double> gas_velocity;
  std::vector<double> grad_p;
  std::vector<double> gas_fraction;
  std::vector<double> mean_diameter;  // local Sauter mean <d> (only for a law that uses it, else empty)
  std::vector<double> class_force;    // force of the missing class collisions (coupling.class_collisions, else empty)
};

class ParcelMeshCoupler {
 public:
  ParcelMeshCoupler(const BackgroundGrid& grid, const CellOwnerMap& owners, TransferKernel kernel, DragLaw drag,
                    DragLimits limits, GasProperties gas);

  // Finds the touched cells of this rank's parcels. Call once per coupling step, after the DEM moved.
  TransferStats beginStep(const ParcelBatch& parcels);

  // a_s on owned cells from the parcels' volumes np V_p (and, for a drag law that uses the local Sauter
  // mean, the moment np dp^2 as well).
  void depositSolids(std::vector<double>& owned_solid_fraction);

  // Gathers a_g and u (owned cell fields, u interleaved xyz) at the parcels, evaluates the drag law
  // (real diameter dp, local a_g, slip; for BVK the local Sauter mean <d> = sum np dp^3 / sum np dp^2,
  // both moments deposited by depositSolids and gathered with the same weights) into kappa, and deposits
  // kappa and kappa v to the owned cells.
  DragStats computeDrag(const std::vector<double>& owned_gas_fraction, const std::vector<double>& owned_velocity,
                        SolidsOnCells& solids, GasAtParcels& at_parcels);

  // Gas velocity and pressure gradient (owned cell fields, interleaved xyz) at the parcels.
  void gatherGas(const std::vector<double>& owned_velocity, const std::vector<double>& owned_grad_p,
                 GasAtParcels& at_parcels);

  // The fluid volume of owned cell c (the background cell's volume off the walls).
  double ownedCellVolume(int c) const { return owned_volume_[c]; }
  int ownedCells() const { return n_owned_; }
  // This step's parcels (those of beginStep).
  const ParcelBatch& parcels() const { return parcels_; }

  // The generic transfers over this step's stencils, for a model beyond the drag (class_collision_exchange.h).
  // `width` values per parcel -> their kernel-weighted sums on the owned cells.
  void depositToOwners(const std::vector<double>& per_parcel, int width, std::vector<double>& owned);
  // The same with every weight squared (sum w^2 q): with depositToOwners' sum w q of the same q it gives the
  // effective number of parcels (sum w q)^2 / sum (w q)^2 that a kernel-weighted mean stands on. Squared per
  // background cell: a gas cell merged from several (cut cells) gets the sum of its members' squares, less
  // than the square of their sum, so its number of parcels comes out too large there.
  void depositSquaredWeightsToOwners(const std::vector<double>& per_parcel, int width, std::vector<double>& owned);
  // `width` values per owned cell -> kernel-weighted means at the parcels (orphans get orphan_value).
  void gatherFromOwned(const std::vector<double>& owned, int width, double orphan_value,
                       std::vector<double>& at_parcels);

 private:
  // Deposits with `stencils` (this step's, or their squares: `squared`) and sums to the owners; a cut cell
  // takes its fluid share (squared) of what the windows put on the whole cell.
  void depositWith(const BoxStencils& stencils, bool squared, const std::vector<double>& per_parcel, int width,
                   std::vector<double>& owned);
  long backgroundCell(int i, int j, int k) const {
    return i + static_cast<long>(grid_.cells[0]) * (j + static_cast<long>(grid_.cells[1]) * k);
  }

  BackgroundGrid grid_;
  CellExchange exchange_;
  TransferKernel kernel_;
  DragLaw drag_;
  DragLimits limits_;
  GasProperties gas_;
  std::vector<double> owned_volume_;  // per owned cell: its fluid volume
  int n_owned_;
  bool uses_mean_diameter_;           // the drag law reads the local Sauter mean
  bool kernel_reads_diameters_;       // the kernel widens for large parcels (coupling.kernel.parcel_scale)
  std::vector<double> owned_moments_;  // per owned cell: sum w np V_p, sum w np dp^2 (if used)

  FluidCells fluid_;  // background cells some rank owns

  ParcelBatch parcels_;
  std::vector<double> diameters_;       // this step's collision diameters, if the kernel reads them
  BoxStencils stencils_;                // this step's stencils
  BoxStencils squared_stencils_;        // their weights squared (depositSquaredWeightsToOwners' work array)
  std::vector<long> touched_;           // the box's fluid cells (background index), exchanged with owners
  std::vector<long> box_of_touched_;    // their box index
  std::vector<double> touched_fraction_;  // their fluid share (below 1 where a wall cuts them)

  // Work arrays of the transfers, kept from step to step so that a coupling step allocates nothing once
  // they have grown to the largest batch and box.
  struct Scratch {
    std::vector<double> on_box, on_touched, owned;               // cell values: box, touched, owned rows
    std::vector<double> per_parcel, gathered, slip, deposited;  // parcel values; drag sums on owned cells
  } scratch_;
};

}  // namespace parcelflow::coupling
