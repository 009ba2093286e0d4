// fix parcel's start-up warning of the geometric limits no contact scaling keeps (geometric_limits.h).
#include <gtest/gtest.h>

#include "liggghts_plugins/geometric_limits.h"

using namespace parcelflow::plugins;

TEST(GeometricLimits, SingleParticlesGetNoWarning)
{
  EXPECT_EQ(geometric_limits_warning("p", 0.002, 1.0), "");
  EXPECT_EQ(geometric_limits_warning("p", 0.002, 0.0), "");  // no parcel measured
}

TEST(GeometricLimits, NamesTheLimitsInTheParcelDiameter)
{
  // np 8 parcels of the dry set's 2 mm glass: D = 4 mm, l = 2
  const std::string text = geometric_limits_warning("cg", 0.004, 2.0);
  EXPECT_NE(text.find("fix cg parcel:"), std::string::npos) << text;
  EXPECT_NE(text.find("D = 0.004 m (l = D/dp up to 2)"), std::string::npos) << text;
  EXPECT_NE(text.find("rule openings at least 57 D (0.228 m) wide"), std::string::npos) << text;  // 57 x 4 mm
  EXPECT_NE(text.find("bodies at least 12.5 D (0.05 m) between walls"), std::string::npos) << text;  // 12.5 x 4 mm
  EXPECT_NE(text.find("(cases/coarse_graining/README.md, \"The rules and their limits\")"), std::string::npos) << text;
  EXPECT_EQ(text.find('%'), std::string::npos) << text;  // the rule, not one set-up's percentages
  EXPECT_EQ(text.find('\n'), std::string::npos);  // one line, as LIGGGHTS prints a warning
}
