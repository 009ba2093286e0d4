#include "liggghts_plugins/geometric_limits.h"

#include <cstdio>

namespace parcelflow::plugins {

std::string geometric_limits_warning(const std::string& fix_id, double largest_diameter,
                                     double largest_scale_factor)
{
  if (!(largest_scale_factor > 1.0)) return "";
  char text[1024];
  std::snprintf(text, sizeof text,
                "fix %s parcel: parcels up to D = %.4g m (l = D/dp up to %.3g) keep no effect of a length of the "
                "set-up over the sphere size, whatever the scaling: an opening narrower than %.0f D (%.3g m) drains "
                "more than 5 %% slower than the particles (slots 6-9 D wide: 15-39 %% slower), and a body less than "
                "%.1f D (%.3g m) between walls packs looser along them (a column 8.3 D wide stood 6 %% taller); "
                "check the walls and openings of the script against these (cases/coarse_graining/dry/README.md)",
                fix_id.c_str(), largest_diameter, largest_scale_factor, kOpeningWidthInDiameters,
                kOpeningWidthInDiameters * largest_diameter, kBodyWidthInDiameters,
                kBodyWidthInDiameters * largest_diameter);
  return text;
}

}  // namespace parcelflow::plugins
