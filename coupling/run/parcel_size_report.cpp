#include "coupling/run/parcel_size_report.h"

#include <cmath>

#include "cfd/base/number_text.hpp"

namespace parcelflow::coupling {

using cfd::formatNumbers;

std::vector<std::string> parcelSizeReport(const ParcelSizes& sizes, const KernelReach& reach) {
  std::vector<std::string> lines;
  // np slightly above 1 from rounding (np = (D/dp)^3 with D = dp) is a bed of single particles
  if (sizes.largest_np <= 1.0 + 1e-9) return lines;
  const double D = sizes.largest_diameter;
  const double across = reach.narrowest_extent / D;  // infinite when every axis is periodic
  lines.push_back(formatNumbers("parcelflow: coarse graining: largest parcel D = %.4g mm (up to %.4g particles)",
                                1e3 * D, sizes.largest_np));
  if (std::isfinite(across))
    lines.back() += formatNumbers(", %.3g parcels across the narrowest extent between walls (%.4g mm)", across,
                                  1e3 * reach.narrowest_extent);
  if (reach.length > 0.0) {
    const double ratio = D / reach.length;
    const bool widened = reach.parcel_scale * D > reach.length;
    const bool smoothed = reach.smoothing_length >= kSmoothingLengthOverDiameter * D;
    lines.back() += formatNumbers("; D / kernel length h (%.4g mm) = %.3g", 1e3 * reach.length, ratio);
    if (widened) lines.back() += formatNumbers(", spread over parcel_scale D = %.4g mm", 1e3 * reach.parcel_scale * D);
    if (reach.smoothing_length > 0.0)
      lines.back() += formatNumbers(", solids fraction smoothed over %.4g mm", 1e3 * reach.smoothing_length);
    if (reach.spills_excess) lines.back() += ", solids above the gas-fraction floor moved to the neighbours";
    if (ratio > kLargestDiameterOverKernelLength && !widened && !smoothed && !reach.spills_excess)
      lines.push_back(formatNumbers("parcelflow: warning: parcels of D = %.4g mm are %.3g times the kernel length h = "
                             "%.4g mm (limit %.3g): each lands in one or two cells and the gas-fraction floor is "
                             "hit often, which drops solids the gas should see; coupling.excess_solids: spill "
                             "keeps them (coupling/README.md)",
                             1e3 * D, ratio, 1e3 * reach.length, kLargestDiameterOverKernelLength));
    else if (ratio > kLargestDiameterOverKernelLengthWithSpill * (1.0 + 1e-9))
      lines.push_back(formatNumbers("parcelflow: warning: parcels of D = %.4g mm are %.3g times the kernel length h = "
                                    "%.4g mm (limit %.3g once the gas-fraction floor drops no solids): ",
                                    1e3 * D, ratio, 1e3 * reach.length, kLargestDiameterOverKernelLengthWithSpill) +
                      "their deposits are lumpy and the gas goes round the lumps; in a fluidized box with periodic "
                      "sides U_mf rose 12.3 % over the particles' at D / h = 2.4 against 1.7-3.9 % at 1.6 "
                      "(cases/coarse_graining/fluidized/README.md); use smaller parcels, or check against a fine run");
  }
  const double wall_share = sizes.largest_excess * reach.side_wall_area_per_volume;
  if (reach.side_wall_area_per_volume > 0.0)
    lines.front() += formatNumbers("; wall layer share (D - d) x side-wall area / gas volume = %.3g", wall_share);
  if (wall_share > kWallLayerShare)
    lines.push_back(formatNumbers("parcelflow: warning: the parcels' wall layer takes a share %.3g of the bed (limit "
                           "%.3g): parcels up to D - d = %.4g mm wider than their particles, along %.4g m2 of side "
                           "wall per m3 of gas. Parcels pack looser along a wall than their particles, and the gas "
                           "passes there: in the measured beds U_mf rose over the particles' by 0.4-0.9 times this "
                           "share (np 8 in a 75 mm bed, share 0.133: +7 %); use smaller parcels or check against a "
                           "fine run",
                           wall_share, kWallLayerShare, 1e3 * sizes.largest_excess, reach.side_wall_area_per_volume));
  if (across < kParcelsAcrossTheNarrowestExtent)
    lines.push_back(formatNumbers("parcelflow: warning: %.3g parcels of D = %.4g mm across the narrowest extent of the "
                           "bed between walls (%.4g mm; limit %.3g): the parcels pack looser at the walls than the particles "
                           "they stand for, and such a bed fluidized later than its particles (the Goldschmidt "
                           "bed's 5 mm parcels, 3 across); use smaller parcels",
                           across, 1e3 * D, 1e3 * reach.narrowest_extent, kParcelsAcrossTheNarrowestExtent));
  const double length_ratio = std::cbrt(sizes.largest_np);  // the largest D / dp
  const bool mixture = sizes.largest_dp > sizes.smallest_dp * (1.0 + 1e-6);
  // one collision diameter for every size: the largest particles are less coarse-grained than the smallest
  if (mixture && D < sizes.largest_dp * length_ratio * (1.0 - 1e-6))
    lines.push_back(formatNumbers("parcelflow: warning: parcels of one diameter D = %.4g mm stand for particles of %.4g "
                                  "to %.4g mm: ",
                                  1e3 * D, 1e3 * sizes.smallest_dp, 1e3 * sizes.largest_dp) +
                    "they pack as spheres of one size do, looser than the mixture (the Goldschmidt beads of 1.5 and "
                    "2.5 mm as 5 mm parcels: solids 0.644 against 0.657), and fluidized 26-28 % later than the "
                    "particles in a box with periodic sides (cases/coarse_graining/fluidized/README.md); fix "
                    "parcel's mode constant_np keeps the mixture's packing");
  if (mixture && length_ratio > kMixtureLengthRatio * (1.0 + 1e-9))
    lines.push_back(formatNumbers("parcelflow: warning: the parcels stand for particles of %.4g to %.4g mm (a size "
                                  "mixture) at up to l = D / dp = %.3g (limit %.3g): ",
                                  1e3 * sizes.smallest_dp, 1e3 * sizes.largest_dp, length_ratio, kMixtureLengthRatio) +
                    "coarse-grained size mixtures segregated by size more than their particles in the measured bed "
                    "(the Goldschmidt beads with a periodic depth, over 10-20 s: beads -0.001, l = 1.5 0.030, l = 2 "
                    "0.774, l = 2 with coupling.class_collisions 0.17-0.33): under one stress the parcels' emulsion "
                    "sheared about l times slower than the particles', and the bed's mixing motion there fell to "
                    "half the particles' at l = 2 (0.75 at l = 1.5); " +
                    (reach.class_collisions
                         ? std::string("coupling.class_collisions (on) restores the classes' collisions the parcels "
                                       "miss, not all of the particles' mixing")
                         : std::string("coupling.class_collisions, off in this run, adds the classes' collisions the "
                                       "parcels miss")) +
                    (reach.keeps_shear_stress
                         ? "; fix parcel's shear_stress (on) kept l = 2 mixed in the mean there (0.005, 0.030 and, "
                           "with coupling.class_collisions, 0.061 in three runs) with bursts to 0.15-0.29 the "
                           "particles do not show, but not between walls 3 parcels apart (0.606)"
                         : "; fix parcel's shear_stress, off here, kept l = 2 mixed in the mean there (0.005, 0.030 "
                           "and, with coupling.class_collisions, 0.061 in three runs), but not between walls 3 "
                           "parcels apart (0.606)") +
                    "; where the classes' mixing matters, use parcels of at most l = " +
                    cfd::shortNumber(kMixtureLengthRatio) +
                    " or check against a fine run (cases/goldschmidt_segregation/README.md, \"Coarse graining: "
                    "causes\")");
  double bubbling_limit = kBubblingLengthRatio;
  if (reach.keeps_shear_stress && !mixture) bubbling_limit = kBubblingLengthRatioOneSizeWithShearStress;
  if (reach.keeps_shear_stress && mixture && reach.class_collisions)
    bubbling_limit = kBubblingLengthRatioMixtureWithShearStressAndClassCollisions;
  if (length_ratio <= bubbling_limit * (1.0 + 1e-9) && bubbling_limit > kBubblingLengthRatio)
    lines.push_back(formatNumbers("parcelflow: coarse graining: l = D / dp = %.3g is within the measured range of fix "
                                  "parcel's shear_stress (l <= %.3g for ",
                                  length_ratio, bubbling_limit) +
                    (mixture ? "a size mixture with coupling.class_collisions" : "one particle size") +
                    "), where the parcels' bed expanded within 5 % of the particles' at about 2 U_mf in a box with "
                    "periodic sides; its voids, though, held 0.70-0.85 of the particles' share of the bed, in voids "
                    "14-20 % narrower (cases/coarse_graining/fluidized/README.md): where bubble sizes matter, check "
                    "them against a fine run");
  else if (length_ratio > kBubblingLengthRatio * (1.0 + 1e-9))
    lines.push_back(formatNumbers("parcelflow: warning: parcels of up to l = D / dp = %.3g bubble less than their "
                                  "particles: ",
                                  length_ratio) +
                    "in the measured fluidized beds (a 37.5 mm box with periodic sides at about 2 U_mf, l = 1.26 to "
                    "2, a mixture and one size) the voids held 1-19 % of the bed against the particles' 14-32 %, the "
                    "bed moved with 0.23-0.57 of their motion and expanded 8-18 % less, with U_mf and the pressure "
                    "drop within 2.3 % (cases/coarse_graining/fluidized/README.md); " +
                    std::string(reach.keeps_shear_stress
                                    ? "with fix parcel's shear_stress, as here, one size expanded within 4 % at "
                                      "l = 2, a mixture within 4 % at l = 1.26 with coupling.class_collisions as well "
                                      "but 5.6-10.3 % less at l = 1.26-2 without it (7.3 % at l = 2 with it), U_mf up "
                                      "to 4.7 % higher: check against a fine run"
                                    : "fix parcel's shear_stress, off here, lowers the parcels' restitution to keep "
                                      "the particles' collisional shear stress (1 - e'^2 = l^4 (1 - e^2)): one size "
                                      "then expanded within 4 % at l = 2, the mixture 5.6-10.3 % less instead of "
                                      "9-18 % (within 4 % at l = 1.26 with coupling.class_collisions as well); where "
                                      "bubbles and expansion matter, use it and check against a fine run"));
  return lines;
}

}  // namespace parcelflow::coupling
