// Arguments of fix parcel/heat: accepted forms and every error message (keyword, value, what is allowed).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "liggghts_plugins/parcel_heat_settings.hpp"

using namespace parcelflow::plugins;

namespace {

std::string errorOf(const std::vector<std::string>& args, int ntypes) {
  try {
    parse_parcel_heat_settings(args, ntypes);
  } catch (const ArgumentError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(ParcelHeatSettings, Accepted) {
  const ParcelHeatSettings s = parse_parcel_heat_settings({"heat_capacity", "840", "1000", "initial_temperature",
                                                           "293.15"}, 2);
  ASSERT_EQ(s.heat_capacity.size(), 2u);
  EXPECT_EQ(s.heat_capacity[0], 840.0);
  EXPECT_EQ(s.heat_capacity[1], 1000.0);
  EXPECT_EQ(s.initial_temperature, 293.15);
  const ParcelHeatSettings t = parse_parcel_heat_settings({"initial_temperature", "400", "heat_capacity", "840"}, 1);
  EXPECT_EQ(t.initial_temperature, 400.0);
  EXPECT_EQ(parse_parcel_heat_settings({"heat_capacity", "840"}, 1).initial_temperature, 0.0);  // not given
}

TEST(ParcelHeatSettings, Errors) {
  EXPECT_EQ(errorOf({"heat_capacity", "-840", "initial_temperature", "300"}, 1),
            "fix parcel/heat: keyword 'heat_capacity' got '-840' for atom type 1; allowed: a specific heat capacity "
            "> 0 J/(kg K)");
  EXPECT_EQ(errorOf({"heat_capacity", "840", "0"}, 2),
            "fix parcel/heat: keyword 'heat_capacity' got '0' for atom type 2; allowed: a specific heat capacity > 0 "
            "J/(kg K)");
  EXPECT_EQ(errorOf({"heat_capacity", "840"}, 2),
            "fix parcel/heat: keyword 'heat_capacity' got 1 values but the box has 2 atom types; allowed: one specific "
            "heat capacity > 0 J/(kg K) per atom type 1..2");
  EXPECT_EQ(errorOf({"initial_temperature", "0", "heat_capacity", "840"}, 1),
            "fix parcel/heat: keyword 'initial_temperature' got '0'; allowed: a temperature > 0 K");
  EXPECT_EQ(errorOf({"initial_temperature", "-3", "heat_capacity", "840"}, 1),
            "fix parcel/heat: keyword 'initial_temperature' got '-3'; allowed: a temperature > 0 K");
  EXPECT_EQ(errorOf({"initial_temperature", "hot", "heat_capacity", "840"}, 1),
            "fix parcel/heat: keyword 'initial_temperature' got 'hot'; allowed: a temperature > 0 K");
  EXPECT_EQ(errorOf({"heat_capacity", "840", "initial_temperature"}, 1),
            "fix parcel/heat: keyword 'initial_temperature' needs a value (a temperature > 0 K)");
  EXPECT_EQ(errorOf({"initial_temperature", "300"}, 1),
            "fix parcel/heat: keyword 'heat_capacity' is missing; allowed: heat_capacity c_1 ... c_N, one specific heat "
            "capacity > 0 J/(kg K) per atom type");
  EXPECT_EQ(errorOf({"heat_capacity", "840", "correlation", "Gunn"}, 1),
            "fix parcel/heat: unknown keyword 'correlation'. allowed keywords: initial_temperature, heat_capacity");
  EXPECT_EQ(errorOf({"heat_capacity", "840", "heat_capacity", "840"}, 1),
            "fix parcel/heat: keyword 'heat_capacity' given twice");
}
