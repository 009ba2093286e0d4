// Settings of a coupled case that belong to the coupling layer: the keys `liggghts`, `time`, `coupling`,
// `output` and `monitors` of case.yaml (the gas keys belong to parcelflow::cfd::GasConfig). Every key, its
// unit and default is documented in coupling/README.md.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace parcelflow::coupling {

struct LiggghtsSettings {
  std::string script;                                      // path relative to the case folder
  std::vector<std::pair<std::string, std::string>> variables;
};

struct TimeSettings {
  double end = 0.0;          // simulated time of the coupled phase [s]
  double gas_step = 0.0;     // gas time step = coupling interval [s]
  double dem_step = 0.0;     // DEM time step [s]; gas_step must be a whole multiple of it
  int demStepsPerGasStep() const;
};

struct KernelSettings {
  std::string type = "gaussian";  // gaussian | centroid
  double sharpness = 1.0;         // a in exp(-a |dx|^2 / h^2) (paper eq. 8): larger is narrower
  int radius = 2;                 // stencil half-width in cells
  // h: "cell_volume" (the cube root of the cell volume: paper eq. 8's one length scale of the cell) or
  // "cell_axes" (the cell's length along each axis: on tall cells it smooths vertically over more metres)
  std::string length_scale = "cell_volume";
  // lambda: a parcel of collision diameter D wider than lambda D > h is spread over h_p = lambda D instead
  // (gaussian only; 0: h for every parcel, the paper's eq. 8 as written)
  double parcel_scale = 0.0;
  // at walls (the background box's faces, cells without fluid, cut cells' cuts): "truncate" (the part beyond a
  // wall is dropped before the weights are renormalised) or "reflect" (image parcels behind the wall)
  std::string boundary = "truncate";
  // L [m]: the deposited solids fraction is smoothed by implicit diffusion over L (cfd/fv/diffusion_smoother.hpp:
  // conservative, no flux through the boundaries); 0: not smoothed
  double smoothing_length = 0.0;
};

// Limits beyond which a run counts as diverged (run/blowup_guard.h); the defaults are far above what the
// shipped cases reach (coupling/README.md, "Blow-up guards").
struct GuardSettings {
  double max_cfl = 1000.0;              // gas Courant number of a step
  double max_continuity_error = 1.0;    // StepReport::continuityError of a step (relative to its gas flow)
  double max_parcel_loss = 0.1;         // parcels lost in one coupling step, as a fraction of the initial count
};

// coupling.filtered_drag: required by, and only allowed with, coupling.drag: RadlSundaresanFilteredBVK.
struct FilteredDragSettings {
  double particle_density = 0.0;  // kg/m^3 of every real particle (for its terminal velocity); > gas.density
  double filter_cells = 1.0;      // filter width Delta in gas cells: Delta = filter_cells (V_cell)^(1/3)
};

// coupling.class_collisions (absent: off): the collisions between the atom types of a size mixture that
// coarse-grained parcels do not make, added as a force (run/class_collision_exchange.h); e and C_f of the
// collisions between the types, as the LIGGGHTS script has them.
struct ClassCollisionSettings {
  bool enabled = false;
  double restitution = 0.0;
  double friction = 0.0;
};

struct CouplingSettings {
  std::string drag = "WenYu";
  FilteredDragSettings filtered_drag;
  KernelSettings kernel;
  double gas_fraction_floor = 0.35;  // a_g is never below this; every hit is counted and reported
  std::string excess_solids = "spill";  // solids above 1 - floor: "spill" (to the neighbours) or "discard" (cut)
  ClassCollisionSettings class_collisions;
  GuardSettings guards;
};

struct OutputSettings {
  std::string folder = "output";
  double fields_interval = 0.0;    // s of simulated time between HDF5 field writes (0: only at the end)
  double parcels_interval = 0.0;   // s between HDF5 parcel writes (0: none)
  double checkpoint_interval = 0.0;  // s between checkpoints (0: only when stopped by a signal)
  double monitor_interval = 0.01;  // s between monitor rows
  double progress_interval = 5.0;  // s of wall time between progress lines
};

struct MonitorSettings {
  std::vector<double> pressure_planes;         // heights z [m] where mean p and a_g are recorded
  std::array<double, 2> bed_pressure_drop{0.0, 0.0};  // heights (low, high) of the bed pressure drop
  bool has_bed_pressure_drop = false;
  double average_start = -1.0;  // monitors.average.start [s]: time averages from then on (< 0: none)
  bool averages() const { return average_start >= 0.0; }
};

struct CaseSettings {
  LiggghtsSettings liggghts;
  TimeSettings time;
  CouplingSettings coupling;
  OutputSettings output;
  MonitorSettings monitors;
};

}  // namespace parcelflow::coupling
