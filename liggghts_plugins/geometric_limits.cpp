#include "liggghts_plugins/geometric_limits.h"

#include <cstdio>

namespace parcelflow::plugins {

std::string geometric_limits_warning(const std::string& fix_id, double largest_diameter,
                                     double largest_scale_factor)
{
  if (!(largest_scale_factor > 1.0)) return "";
  char text[1024];
  std::snprintf(text, sizeof text,
                "fix %s parcel: parcels up to D = %.4g m (l = D/dp up to %.3g): rule openings at least %.0f D "
                "(%.3g m) wide and bodies at least %.1f D (%.3g m) between walls; narrower openings drain slower and "
                "narrower bodies pack looser along their walls than the particles, whatever the scaling. Check the "
                "script's walls and openings against them (cases/coarse_graining/README.md, \"The rules and their "
                "limits\")",
                fix_id.c_str(), largest_diameter, largest_scale_factor, kOpeningWidthInDiameters,
                kOpeningWidthInDiameters * largest_diameter, kBodyWidthInDiameters,
                kBodyWidthInDiameters * largest_diameter);
  return text;
}

}  // namespace parcelflow::plugins
