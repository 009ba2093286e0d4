// What no contact scaling keeps: effects of a length of the set-up over the sphere diameter, a ratio that
// falls by l = D/dp for parcels (issue 29; the runs: cases/coarse_graining/dry/README.md, 2026-12-04).
// The walls and openings are the input script's, which fix parcel does not measure, so it names the limits
// in the parcels' own diameter at the start of a run with parcels of more than one particle.
#pragma once

#include <string>

namespace parcelflow::plugins {

// Openings: the empty annulus at a slot's edge was 1.9 D for parcels (np 8 and 27, scaling linear and none)
// against 0.49 dp for the particles, so a slot W drains as one of W - 1.9 D wide; (1 - 1.9 D / W)^1.5 >= 0.95
// needs W >= 57 D. Slots 6-9 D wide drained 12-34 % below Beverloo's law at D and 15-39 % below the particles.
constexpr double kOpeningWidthInDiameters = 57.0;
// Bodies between walls: a collapsing column 12.5 D wide (np 8, linear) kept run-out, height at the wall and
// centroid travel within 5 % of the particles'; 8.3 D wide (np 27) it packed looser along its walls, stood
// 6 % taller and its final height at the wall and centroid travel were off by -9.4 and +7.5 %.
constexpr double kBodyWidthInDiameters = 12.5;

// The warning for parcels up to largest_diameter (D) and up to largest_scale_factor (l = D/dp); empty for
// l <= 1 (every sphere one particle).
std::string geometric_limits_warning(const std::string& fix_id, double largest_diameter,
                                     double largest_scale_factor);

}  // namespace parcelflow::plugins
