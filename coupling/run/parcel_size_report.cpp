#include "coupling/run/parcel_size_report.h"

#include <cmath>

#include "cfd/base/number_text.hpp"

namespace parcelflow::coupling {

using cfd::formatNumbers;

namespace {
// Where each rule's runs and measured costs are.
constexpr const char* kRulesSection = "(cases/coarse_graining/README.md, \"The rules and their limits\")";
}  // namespace

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
      lines.push_back(formatNumbers("parcelflow: warning: rule D / h <= %.3g with the gas-fraction floor's excess "
                                    "discarded: here D = %.4g mm over h = %.4g mm is %.3g; each parcel lands in one "
                                    "or two cells and the floor drops solids the gas should see. Use "
                                    "coupling.excess_solids: spill, or smaller parcels ",
                                    kLargestDiameterOverKernelLength, 1e3 * D, 1e3 * reach.length, ratio) +
                                    kRulesSection);
    else if (ratio > kLargestDiameterOverKernelLengthWithSpill * (1.0 + 1e-9))
      lines.push_back(formatNumbers("parcelflow: warning: rule D / h <= %.3g: here D = %.4g mm over h = %.4g mm is "
                                    "%.3g; deposits that large are lumpy and the gas goes round them, so the bed "
                                    "fluidizes later than its particles. Use smaller parcels or check against a "
                                    "fine run ",
                                    kLargestDiameterOverKernelLengthWithSpill, 1e3 * D, 1e3 * reach.length, ratio) +
                                    kRulesSection);
  }
  const double wall_share = sizes.largest_excess * reach.side_wall_area_per_volume;
  if (reach.side_wall_area_per_volume > 0.0)
    lines.front() += formatNumbers("; wall layer share (D - d) x side-wall area / gas volume = %.3g", wall_share);
  if (wall_share > kWallLayerShare)
    lines.push_back(formatNumbers("parcelflow: warning: rule wall layer share (D - d) x side-wall area / gas volume "
                                  "<= %.3g: here %.3g (parcels up to D - d = %.4g mm wider than their particles, "
                                  "%.4g m2 of side wall per m3 of gas); parcels pack looser along a wall than their "
                                  "particles and the gas passes there, so the bed fluidizes later. Use smaller "
                                  "parcels or check against a fine run ",
                                  kWallLayerShare, wall_share, 1e3 * sizes.largest_excess,
                                  reach.side_wall_area_per_volume) +
                                  kRulesSection);
  if (across < kParcelsAcrossTheNarrowestExtent)
    lines.push_back(formatNumbers("parcelflow: warning: rule at least %.3g parcels across the narrowest extent between "
                                  "walls: here %.3g parcels of D = %.4g mm across %.4g mm; so few parcels across pack "
                                  "looser at the walls and may not fluidize where their particles do. Use smaller "
                                  "parcels ",
                                  kParcelsAcrossTheNarrowestExtent, across, 1e3 * D, 1e3 * reach.narrowest_extent) +
                                  kRulesSection);
  const double length_ratio = std::cbrt(sizes.largest_np);  // the largest D / dp
  const bool mixture = sizes.largest_dp > sizes.smallest_dp * (1.0 + 1e-6);
  // one collision diameter for every size: the largest particles are less coarse-grained than the smallest
  if (mixture && D < sizes.largest_dp * length_ratio * (1.0 - 1e-6))
    lines.push_back(formatNumbers("parcelflow: warning: rule a size mixture keeps its size ratio (fix parcel mode "
                                  "constant_np): here parcels of one diameter D = %.4g mm stand for particles of "
                                  "%.4g to %.4g mm; they pack as spheres of one size do, looser than the mixture, "
                                  "so the bed fluidizes later than its particles ",
                                  1e3 * D, 1e3 * sizes.smallest_dp, 1e3 * sizes.largest_dp) +
                                  kRulesSection);
  if (mixture && length_ratio > kMixtureLengthRatio * (1.0 + 1e-9))
    lines.push_back(formatNumbers("parcelflow: warning: rule l = D / dp <= %.3g for a size mixture whose mixing "
                                  "matters: here l = %.3g for particles of %.4g to %.4g mm; coarse-grained mixtures "
                                  "segregated by size more than their particles. ",
                                  kMixtureLengthRatio, length_ratio, 1e3 * sizes.smallest_dp,
                                  1e3 * sizes.largest_dp) +
                    (reach.class_collisions ? "coupling.class_collisions (on here) restores part of the mixing; "
                                            : "coupling.class_collisions (off here) restores part of the mixing; ") +
                    "check against a fine run " + kRulesSection);
  double bubbling_limit = kBubblingLengthRatio;
  if (reach.keeps_shear_stress && !mixture) bubbling_limit = kBubblingLengthRatioOneSizeWithShearStress;
  if (reach.keeps_shear_stress && mixture && reach.class_collisions)
    bubbling_limit = kBubblingLengthRatioMixtureWithShearStressAndClassCollisions;
  const std::string kind =
      std::string(mixture ? "a size mixture" : "one size") +
      (reach.keeps_shear_stress ? " with fix parcel's shear_stress" : "") +
      (mixture && reach.keeps_shear_stress && reach.class_collisions ? " and coupling.class_collisions" : "");
  if (length_ratio <= bubbling_limit * (1.0 + 1e-9) && bubbling_limit > kBubblingLengthRatio)
    lines.push_back(formatNumbers("parcelflow: coarse graining: l = D / dp = %.3g is within the range where the "
                                  "validation runs kept the expansion of ",
                                  length_ratio) +
                    kind + formatNumbers(" (l <= %.3g); the voids' share of the bed was not kept there: where bubble "
                                         "sizes matter, check against a fine run ",
                                         bubbling_limit) +
                    kRulesSection);
  else if (length_ratio > kBubblingLengthRatio * (1.0 + 1e-9))
    lines.push_back(formatNumbers("parcelflow: warning: rule l = D / dp <= %.3g for the bubbling and expansion of ",
                                  bubbling_limit) +
                    kind + formatNumbers(": here l = %.3g; coarse-grained beds beyond it bubbled and expanded "
                                         "differently from their particles, less in some beds and more in others, so "
                                         "neither the size nor the sign of the difference is known for this bed. ",
                                         length_ratio) +
                    (reach.keeps_shear_stress ? std::string("Check against a fine run ")
                                              : std::string("fix parcel's shear_stress (off here) widens the range "
                                                            "where the particles' restitution allows it; check "
                                                            "against a fine run ")) +
                    kRulesSection);
  return lines;
}

}  // namespace parcelflow::coupling
