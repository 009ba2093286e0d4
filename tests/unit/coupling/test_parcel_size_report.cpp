// The start-up report on coarse-grained parcels: silent for single particles, a description for parcels,
// and a warning naming the ratio and the limit for each limit broken.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "coupling/run/parcel_size_report.h"

namespace pc = parcelflow::coupling;

namespace {

bool mentions(const std::string& line, const std::string& what) { return line.find(what) != std::string::npos; }

// Every warning names its rule and the report section that holds the rule's runs.
const std::string kSection = "(cases/coarse_graining/README.md, \"The rules and their limits\")";

bool namesRuleAndSection(const std::string& line) {
  return mentions(line, "parcelflow: warning: rule ") && mentions(line, kSection);
}

// The report without its last line, the bubbling warning that every coarse-grained bed gets (checked here).
std::vector<std::string> withoutBubbling(std::vector<std::string> lines) {
  EXPECT_FALSE(lines.empty());
  if (lines.empty()) return lines;
  EXPECT_TRUE(mentions(lines.back(), "for the bubbling and expansion of")) << lines.back();
  EXPECT_TRUE(namesRuleAndSection(lines.back())) << lines.back();
  lines.pop_back();
  return lines;
}

// The Goldschmidt bed's mesh: h = 4.15 mm, 15 mm deep.
const pc::KernelReach kGoldschmidt{0.00415, 0.0, 0.015};

}  // namespace

TEST(ParcelSizeReport, SilentForSingleParticles) {
  EXPECT_TRUE(pc::parcelSizeReport({0.0025, 1.0}, kGoldschmidt).empty());
}

TEST(ParcelSizeReport, WarnsForParcelsWiderThanTheKernelAndTooFewAcross) {
  // 5 mm parcels: D/h = 1.2 > 1 with parcel_scale 0, and 3 across the 15 mm depth < 6
  const auto lines = withoutBubbling(pc::parcelSizeReport({0.005, 37.04}, kGoldschmidt));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_TRUE(mentions(lines[0], "D = 5 mm")) << lines[0];
  EXPECT_TRUE(mentions(lines[1], "rule D / h <= 1 with the gas-fraction floor's excess discarded: here D = 5 mm "
                                 "over h = 4.15 mm is 1.2")) << lines[1];
  EXPECT_TRUE(namesRuleAndSection(lines[1])) << lines[1];
  EXPECT_TRUE(mentions(lines[2], "rule at least 6 parcels across the narrowest extent between walls: here 3 parcels "
                                 "of D = 5 mm across 15 mm")) << lines[2];
  EXPECT_TRUE(namesRuleAndSection(lines[2])) << lines[2];
}

TEST(ParcelSizeReport, AWidenedKernelAndAWideBedAreWithinTheLimits) {
  pc::KernelReach widened = kGoldschmidt;
  widened.parcel_scale = 2.0;
  widened.narrowest_extent = 0.03;  // 6 parcels across
  const auto lines = withoutBubbling(pc::parcelSizeReport({0.005, 8.0}, widened));
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_TRUE(mentions(lines[0], "spread over parcel_scale D = 10 mm")) << lines[0];
  // smoothed over at least D/2 instead: no kernel warning, and the description says so
  pc::KernelReach smoothed = widened;
  smoothed.parcel_scale = 0.0;
  smoothed.smoothing_length = 0.0025;
  const auto smooth_lines = withoutBubbling(pc::parcelSizeReport({0.005, 8.0}, smoothed));
  ASSERT_EQ(smooth_lines.size(), 1u);
  EXPECT_TRUE(mentions(smooth_lines[0], "smoothed over 2.5 mm")) << smooth_lines[0];
  smoothed.smoothing_length = 0.002;  // less than D/2: the warning stays
  EXPECT_EQ(withoutBubbling(pc::parcelSizeReport({0.005, 8.0}, smoothed)).size(), 2u);
  // spilling the excess solids instead: no kernel warning either, and the description says so
  pc::KernelReach spilled = widened;
  spilled.parcel_scale = 0.0;
  spilled.spills_excess = true;
  const auto spill_lines = withoutBubbling(pc::parcelSizeReport({0.005, 8.0}, spilled));
  ASSERT_EQ(spill_lines.size(), 1u);
  EXPECT_TRUE(mentions(spill_lines[0], "moved to the neighbours")) << spill_lines[0];
  // np 8 parcels of 3 mm (the np8 bed's small class alone): D/h = 0.72, 5 across: only the second limit
  EXPECT_EQ(withoutBubbling(pc::parcelSizeReport({0.003, 8.0}, kGoldschmidt)).size(), 2u);
}

TEST(ParcelSizeReport, WarnsWhenTheWallLayerTakesMoreThanItsShare) {
  // the 75 mm fluidized bed (cases/coarse_graining/fluidized): 3.26 mm cells, four side walls, 4 / 0.075 m2 per m3
  pc::KernelReach bed{0.075 / 23, 0.0, 0.075};
  bed.spills_excess = true;
  bed.side_wall_area_per_volume = 4.0 / 0.075;
  // np 8: 5 mm parcels of 2.5 mm beads, share 4 x 2.5 / 75 = 0.133
  const auto lines = withoutBubbling(pc::parcelSizeReport({0.005, 8.0, 0.0025}, bed));
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_TRUE(mentions(lines[0], "wall layer share (D - d) x side-wall area / gas volume = 0.133")) << lines[0];
  EXPECT_TRUE(mentions(lines[1], "rule wall layer share (D - d) x side-wall area / gas volume <= 0.05: here 0.133"))
      << lines[1];
  EXPECT_TRUE(mentions(lines[1], "D - d = 2.5 mm")) << lines[1];
  EXPECT_TRUE(namesRuleAndSection(lines[1])) << lines[1];
  // the same parcels in a 0.3 m bed: share 0.033, only the description
  bed.side_wall_area_per_volume = 4.0 / 0.3;
  bed.narrowest_extent = 0.3;
  EXPECT_EQ(withoutBubbling(pc::parcelSizeReport({0.005, 8.0, 0.0025}, bed)).size(), 1u);
  // periodic sides (no side wall counted): no share in the description
  bed.side_wall_area_per_volume = 0.0;
  const auto periodic = withoutBubbling(pc::parcelSizeReport({0.005, 8.0, 0.0025}, bed));
  ASSERT_EQ(periodic.size(), 1u);
  EXPECT_FALSE(mentions(periodic[0], "wall layer")) << periodic[0];
  // every axis periodic (no walls to count parcels between): neither a count across nor its warning
  bed.narrowest_extent = std::numeric_limits<double>::infinity();
  const auto unbounded = withoutBubbling(pc::parcelSizeReport({0.005, 8.0, 0.0025}, bed));
  ASSERT_EQ(unbounded.size(), 1u);
  EXPECT_FALSE(mentions(unbounded[0], "across")) << unbounded[0];
}

TEST(ParcelSizeReport, WarnsForACoarseGrainedSizeMixture) {
  // the Goldschmidt beads as np 8 parcels in the periodic-depth bed: 1.5 and 2.5 mm beads, l = 2
  pc::KernelReach periodic = kGoldschmidt;
  periodic.parcel_scale = 2.0;
  periodic.narrowest_extent = 0.15;
  const pc::ParcelSizes np8{0.005, 8.0, 0.0025, 0.0015, 0.0025};
  const auto lines = withoutBubbling(pc::parcelSizeReport(np8, periodic));
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_TRUE(mentions(lines[1], "rule l = D / dp <= 1.5 for a size mixture whose mixing matters: here l = 2 for "
                                 "particles of 1.5 to 2.5 mm")) << lines[1];
  EXPECT_TRUE(mentions(lines[1], "coupling.class_collisions (off here) restores part")) << lines[1];
  EXPECT_TRUE(namesRuleAndSection(lines[1])) << lines[1];
  periodic.class_collisions = true;
  EXPECT_TRUE(mentions(withoutBubbling(pc::parcelSizeReport(np8, periodic))[1],
                       "coupling.class_collisions (on here) restores"));
  periodic.class_collisions = false;
  // np 3.375 (l = 1.5), which remixed as the beads do: within the limit
  EXPECT_EQ(withoutBubbling(pc::parcelSizeReport({0.00375, 3.375, 0.00125, 0.0015, 0.0025}, periodic)).size(), 1u);
  // one particle size in parcels: no mixture warning
  EXPECT_EQ(withoutBubbling(pc::parcelSizeReport({0.005, 8.0, 0.0025, 0.0025, 0.0025}, periodic)).size(), 1u);
  // a mixture of single particles: no report at all
  EXPECT_TRUE(pc::parcelSizeReport({0.0025, 1.0, 0.0, 0.0015, 0.0025}, periodic).empty());
}

TEST(ParcelSizeReport, TellsACoarseGrainedBedOutsideTheValidatedBubblingRangeWithoutGuessingTheSign) {
  // np 2 (l = 1.26), the smallest l measured: beyond the rule l <= 1 without shear_stress
  pc::KernelReach periodic = kGoldschmidt;
  periodic.narrowest_extent = std::numeric_limits<double>::infinity();
  periodic.spills_excess = true;
  const pc::ParcelSizes np2{0.00315, 2.0, 0.00065, 0.0025, 0.0025};
  const auto lines = pc::parcelSizeReport(np2, periodic);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_TRUE(mentions(lines[1], "rule l = D / dp <= 1 for the bubbling and expansion of one size: here l = 1.26"))
      << lines[1];
  // beds beyond the rule expanded less in some beds and more in others: no sign, no percentage is promised
  EXPECT_TRUE(mentions(lines[1], "neither the size nor the sign of the difference is known")) << lines[1];
  EXPECT_FALSE(mentions(lines[1], "%")) << lines[1];
  EXPECT_TRUE(mentions(lines[1], "shear_stress (off here)")) << lines[1];
  EXPECT_TRUE(namesRuleAndSection(lines[1])) << lines[1];
  // with shear_stress one size is within the range up to l = 2: said, not warned, and the voids not promised
  periodic.keeps_shear_stress = true;
  for (const pc::ParcelSizes& oneSize : {np2, pc::ParcelSizes{0.005, 8.0, 0.0025, 0.0025, 0.0025}}) {
    const auto kept = pc::parcelSizeReport(oneSize, periodic);
    ASSERT_EQ(kept.size(), 2u);
    EXPECT_FALSE(mentions(kept[1], "warning")) << kept[1];
    EXPECT_TRUE(mentions(kept[1], "the expansion of one size with fix parcel's shear_stress (l <= 2)")) << kept[1];
    EXPECT_TRUE(mentions(kept[1], "the voids' share of the bed was not kept there")) << kept[1];
    EXPECT_TRUE(mentions(kept[1], kSection)) << kept[1];
  }
  // beyond l = 2 (np 27) it is warned again, naming the rule with shear_stress
  const auto np27 = pc::parcelSizeReport({0.0075, 27.0, 0.005, 0.0025, 0.0025}, periodic);
  ASSERT_EQ(np27.size(), 3u);  // with the warning of parcels 1.8 times h (the next test)
  EXPECT_TRUE(mentions(np27[2], "rule l = D / dp <= 2 for the bubbling and expansion of one size with fix parcel's "
                                "shear_stress: here l = 3")) << np27[2];
  EXPECT_FALSE(mentions(np27[2], "off here")) << np27[2];
  // a size mixture at l = 1.26: warned with shear_stress alone, within the range with coupling.class_collisions
  const pc::ParcelSizes mixtureNp2{0.00315, 2.0, 0.00065, 0.0015, 0.0025};
  EXPECT_TRUE(mentions(pc::parcelSizeReport(mixtureNp2, periodic).back(),
                       "rule l = D / dp <= 1 for the bubbling and expansion of a size mixture with fix parcel's "
                       "shear_stress: here l = 1.26"));
  periodic.class_collisions = true;
  const auto both = pc::parcelSizeReport(mixtureNp2, periodic);
  ASSERT_EQ(both.size(), 2u);
  EXPECT_TRUE(mentions(both[1], "a size mixture with fix parcel's shear_stress and coupling.class_collisions "
                                "(l <= 1.26)")) << both[1];
  // and warned at l = 1.5 with both
  EXPECT_TRUE(mentions(pc::parcelSizeReport({0.00375, 3.375, 0.00125, 0.0015, 0.0025}, periodic).back(),
                       "coupling.class_collisions: here l = 1.5"));
  // single particles: no report, so no warning
  EXPECT_TRUE(pc::parcelSizeReport({0.0025, 1.0, 0.0, 0.0025, 0.0025}, periodic).empty());
}

TEST(ParcelSizeReport, WarnsForParcelsFarWiderThanTheKernelEvenWithTheExcessSpilled) {
  // the periodic fluidized box: 3.125 mm cells, spill; np 8 (5 mm, D/h 1.6) kept U_mf, np 27 (7.5 mm, 2.4) not
  pc::KernelReach box{0.003125, 0.0, std::numeric_limits<double>::infinity()};
  box.spills_excess = true;
  EXPECT_EQ(withoutBubbling(pc::parcelSizeReport({0.005, 8.0, 0.0025, 0.0015, 0.0025}, box)).size(), 2u);  // + mixture
  const auto np27 = withoutBubbling(pc::parcelSizeReport({0.0075, 27.0, 0.005, 0.0025, 0.0025}, box));
  ASSERT_EQ(np27.size(), 2u);
  EXPECT_TRUE(mentions(np27[1], "rule D / h <= 1.6: here D = 7.5 mm over h = 3.125 mm is 2.4")) << np27[1];
  EXPECT_TRUE(namesRuleAndSection(np27[1])) << np27[1];
  EXPECT_FALSE(mentions(np27[1], "%")) << np27[1];  // the rule, not one box's percentages
  // without spill the floor's warning (limit 1) says it instead, once
  box.spills_excess = false;
  const auto unspilled = withoutBubbling(pc::parcelSizeReport({0.0075, 27.0, 0.005, 0.0025, 0.0025}, box));
  ASSERT_EQ(unspilled.size(), 2u);
  EXPECT_TRUE(mentions(unspilled[1], "rule D / h <= 1 with the gas-fraction floor's excess discarded")) << unspilled[1];
}

TEST(ParcelSizeReport, WarnsForOneParcelDiameterOverASizeMixture) {
  pc::KernelReach box{0.003125, 0.0, std::numeric_limits<double>::infinity()};
  box.spills_excess = true;
  // the Goldschmidt beads as 5 mm parcels (mode constant_diameter): np 37.04 for the small, 8 for the large
  const auto d5mm = pc::parcelSizeReport({0.005, 37.04, 0.0035, 0.0015, 0.0025}, box);
  const auto warned = [](const std::vector<std::string>& lines) {
    int n = 0;
    for (const auto& line : lines) n += mentions(line, "parcels of one diameter");
    return n;
  };
  ASSERT_EQ(warned(d5mm), 1) << d5mm.size();
  for (const auto& line : d5mm)
    if (mentions(line, "parcels of one diameter"))
      EXPECT_TRUE(mentions(line, "rule a size mixture keeps its size ratio (fix parcel mode constant_np): here "
                                 "parcels of one diameter D = 5 mm stand for particles of 1.5 to 2.5 mm"))
          << line;
  // as np 8 parcels (3 and 5 mm: the mixture's size ratio) and as one size: not told
  EXPECT_EQ(warned(pc::parcelSizeReport({0.005, 8.0, 0.0025, 0.0015, 0.0025}, box)), 0);
  EXPECT_EQ(warned(pc::parcelSizeReport({0.005, 8.0, 0.0025, 0.0025, 0.0025}, box)), 0);
  // 2.5 mm parcels: the large beads single, the small ones 4.63 per parcel
  EXPECT_EQ(warned(pc::parcelSizeReport({0.0025, 4.63, 0.001, 0.0015, 0.0025}, box)), 1);
}
