// What coarse-grained parcels are against the gas mesh and the bed, said at the first coupling step
// (issue 29: a case outside the measured range is told so at its start, naming the ratio and the limit).
// The limits and the runs behind them: cases/goldschmidt_segregation/README.md, "Coarse graining: causes".
#pragma once

#include <string>
#include <vector>

namespace parcelflow::coupling {

// Over all parcels of the run (the caller reduces them over the ranks).
struct ParcelSizes {
  double largest_diameter = 0.0;  // collision diameter D = dp np^(1/3) [m]
  double largest_np = 0.0;        // real particles per parcel
  double largest_excess = 0.0;    // D - dp: how much wider than its particles a parcel is [m]
  double smallest_dp = 0.0;       // the parcels' smallest and largest real particle diameter [m]
  double largest_dp = 0.0;
};

struct KernelReach {
  double length = 0.0;          // h of the gaussian kernel [m] (0: a kernel without one, the centroid)
  double parcel_scale = 0.0;    // coupling.kernel.parcel_scale
  double narrowest_extent = 0.0;  // the gas box's smallest length between walls (not periodic for the DEM) [m]
  double smoothing_length = 0.0;  // coupling.kernel.smoothing_length [m]
  bool spills_excess = false;     // coupling.excess_solids: spill (the floor keeps the solids volume)
  double side_wall_area_per_volume = 0.0;  // side_walls.h [1/m]
  bool class_collisions = false;  // coupling.class_collisions is on
  bool keeps_shear_stress = false;  // fix parcel's shear_stress is on (the parcels' restitution lowered)
};

// Parcels wider than the kernel length, with the kernel not widened for them: the gas-fraction floor hits
// of the 5 mm Goldschmidt parcels (D/h = 1.2), 308,000 cell-steps over 1 s; 132,000 with parcel_scale 2,
// none with parcel_scale 2 and reflecting faces (392,000 with parcel_scale 1, which widens them by 1.2 only).
// Spilling the excess (coupling.excess_solids: spill) keeps the solids the floor would drop: the np 8 bed's
// packed-branch drag then matched the beads' (periodic fluidized bed, cases/coarse_graining/fluidized/README.md).
constexpr double kLargestDiameterOverKernelLength = 1.0;
// With the excess spilled (or the kernel widened or smoothed) the periodic fluidized box's U_mf stayed within 5 %
// of the beads' up to D/h = 1.6 (np 8 of the Goldschmidt beads on 3.125 mm cells: +1.7 / +3.9 %, two seeds) and
// rose 12.3 % at D/h = 2.4 (np 27; +9.7 % with parcel_scale 1): its deposits reach a solids fraction of 3 in one
// cell and the gas goes round the lumps (cases/coarse_graining/fluidized/README.md).
constexpr double kLargestDiameterOverKernelLengthWithSpill = 1.6;
// A smoothing length of at least this share of D also spreads the parcels: L = D/2 removed every floor hit of
// the np 8 parcels (5 mm) in the 75 mm fluidized bed (2.6 million cell-steps without) and 98 % of np 27's
// (7.5 mm, L = 3.75 mm: 0.33 million left of 15.3), cases/coarse_graining/fluidized/README.md.
constexpr double kSmoothingLengthOverDiameter = 0.5;
// Fewer parcels across the bed's narrowest extent: 5 mm parcels of the Goldschmidt beads (constant
// diameter, np 37 and 8) stayed a fixed bed at 1.1 m/s in the 15 mm deep bed (3 across; with every kernel
// variant tried, rms of the class heights below 1e-3 mm), and fluidized in a 30 mm deep copy of it (6
// across: rms 0.48 mm, 0.43 bubbles per snapshot), where the beads bubble in both. In the 15 mm bed the
// parcels pack looser at the walls than the beads they stand for (solids volume of the wall cells 0.78
// of the middle cells', the beads' 0.93).
constexpr double kParcelsAcrossTheNarrowestExtent = 6.0;
// The share of the bed in the parcels' looser wall layer, (D - d) times the side-wall area per gas volume
// (side_walls.h). In the 75 mm fluidized bed (cases/coarse_graining/fluidized/README.md) the exact sphere
// volume in the cells along the walls was 0.563 of the cell for np 8, 0.522 for np 27, 0.608 for the beads
// (0.65-0.66 inside for all), and the walls raised U_mf over the beads' by 6.7-11.2 % more than in the same bed
// with periodic sides (np 8 at share 0.133: +9.5 % against +2.8 %; np 27 at 0.267: +23.5 against +12.3 %;
// 5 mm parcels at 0.187: +34.2 against +27.5 %); np 8 in the 20 mm fluidized column (0.2): +17.7 % with walls,
// within 5 % without. U_mf rose by 0.36-0.89 times the share: 0.05 keeps it within about 5 %.
constexpr double kWallLayerShare = 0.05;
// Parcels of a size mixture (particles of more than one diameter) up to this length ratio l = D / dp: the
// Goldschmidt beads (1.5 and 2.5 mm, 1.1 m/s) with a periodic depth stayed mixed over 10-20 s (segregation
// -0.001); their parcels at l = 1.5 (np 3.375) segregated in bursts of up to 0.17 and remixed (0.030 over
// 10-20 s); at l = 2 (np 8) they segregated steadily to 0.774, and to 0.724 with the beads' collisional losses
// per unit mass (restitution and friction corrected), and to 0.168 with coupling.class_collisions, which keeps
// the limit until a run with it comes within 0.05 of the particles. With fix parcel's shear_stress l = 2 ended at
// 0.005 and (with the class model too) 0.061, with bursts to 0.29 that remixed: one run of two inside 0.05, so
// the limit stays and the warning says what shear_stress gave.
constexpr double kMixtureLengthRatio = 1.5;
// Parcels of one diameter over a size mixture (mode constant_diameter) pack as spheres of one size do, looser than
// the mixture: the Goldschmidt beads (1.5 / 2.5 mm) as 5 mm parcels settled at solids 0.644 against 0.657 (gas
// fraction 0.356 against 0.343, +19 % of U_mf through Wen-Yu's a_g^4.65 alone) and fluidized 25.8-27.5 % later than
// the beads (periodic box; cases/coarse_graining/fluidized/README.md). Told at any l: no size of it was measured
// within 5 %. (Parcels of constant_np keep the mixture's size ratio, so its packing.)
// Parcels of any l = D / dp above this bubble less than their particles: fluidized at 1.3 m/s in a 37.5 mm box
// with periodic sides (cases/coarse_graining/fluidized/README.md, 2026-12-06), the Goldschmidt beads expanded
// 1.48 times, their parcels 1.35 (l = 1.26), 1.27 (l = 1.5) and 1.22 (l = 2, two seeds), 2 mm beads of one size
// 1.29 and their parcels 1.19 (l = 1.5) and 1.17 (l = 2); voids held 32 and 14 % of the beads' beds and 1-19 %
// of the parcels', around emulsions within 0.014 of one gas fraction, with U_mf within 2.3 %. No l measured
// above 1 kept the expansion within 5 %, so every coarse-grained bed is told. With fix parcel's shear_stress
// (1 - e'^2 = l^4 (1 - e^2)) the mixture was 5.6-10.3 % short at l = 1.26-2 (7.3 % at l = 2 with
// coupling.class_collisions), U_mf up to +4.7 %: told what it gains, and a bed with it what is left.
constexpr double kBubblingLengthRatio = 1.0;
// With fix parcel's shear_stress the beds that expanded within 5 % of their particles in that box: one size at
// l = 2 (-2.8 and -4.0 % with two seeds, U_mf -2.1 / +2.5 %), and the mixture at l = 1.26 (np 2) with
// coupling.class_collisions as well (-4.0 and -3.9 % with two seeds, U_mf +1.7 %), not without it (-5.6 %) nor
// at l = 1.5 (-5.4 and -6.3 %) or 2 (-7.3 %) with it. Up to these the bubbling warning gives way to a line saying so,
// and that their voids were not kept: 0.70 / 0.73 (one size) and 0.84 / 0.85 (mixture) of the beads' share of the
// bed, 14-20 % narrower, so the 15 % on bubbles is not met there.
constexpr double kBubblingLengthRatioOneSizeWithShearStress = 2.0;
constexpr double kBubblingLengthRatioMixtureWithShearStressAndClassCollisions = 1.26;  // np 2: l = 1.2599

// Lines to print: one describing the parcels (only when some parcel holds more than one particle), then one
// warning per limit broken, or a line saying that the bed is within the measured bubbling range. Empty for a
// bed of single particles.
std::vector<std::string> parcelSizeReport(const ParcelSizes& sizes, const KernelReach& reach);

}  // namespace parcelflow::coupling
