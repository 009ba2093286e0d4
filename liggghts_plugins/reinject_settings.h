// Settings of `fix ID group parcel/reinject ...` and their parser (plain C++, unit-tested; throws
// ArgumentError naming the keyword, the value and what is allowed). Region IDs are checked by the fix.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace parcelflow::plugins {

struct ReinjectSettings {
  std::string outlet;                 // region: parcels whose centre is inside are taken out
  std::string return_region;          // region: where they are put back
  std::array<double, 3> velocity{};   // velocity of a reinjected parcel
  long every = 1;                     // reinject on steps that are multiples of `every`
  std::uint32_t seed = 12345679;      // random positions in the return region
  int attempts = 100;                 // candidate positions per parcel and reinjection step
  bool lowest = false;                // placement lowest: the free candidate lowest in z, not the first
};

// Parses the arguments after the style name, e.g. {"outlet","top","return","bottom","velocity","0","0","1"}.
ReinjectSettings parse_reinject_settings(const std::vector<std::string>& args);

}  // namespace parcelflow::plugins
