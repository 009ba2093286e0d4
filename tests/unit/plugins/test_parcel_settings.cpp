// Argument parsing of `fix ID group parcel ...` and `fix ID group parcel/reinject ...`: accepted forms and
// the error messages.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "liggghts_plugins/parcel_settings.h"
#include "liggghts_plugins/reinject_settings.h"

using namespace parcelflow::plugins;

namespace {

std::vector<std::string> split(const std::string& s)
{
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

ParcelSettings parse(const std::string& s) { return parse_parcel_settings(split(s)); }

// Expects an ArgumentError from parser(args) whose message contains every fragment.
template <class Parser>
void expect_error_of(Parser parser, const std::string& args, const std::vector<std::string>& fragments)
{
  try {
    parser(split(args));
    ADD_FAILURE() << "no error for: " << args;
  } catch (const ArgumentError& e) {
    const std::string msg = e.what();
    std::cout << "[ message ] " << args << "\n            -> " << msg << "\n";
    for (const auto& f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << "'" << f << "' not in: " << msg;
  }
}

void expect_error(const std::string& args, const std::vector<std::string>& fragments)
{
  expect_error_of(parse_parcel_settings, args, fragments);
}

void expect_reinject_error(const std::string& args, const std::vector<std::string>& fragments)
{
  expect_error_of(parse_reinject_settings, args, fragments);
}

}  // namespace

TEST(ParcelSettings, ConstantNp)
{
  const ParcelSettings s = parse("mode constant_np np 8");
  EXPECT_EQ(s.mode, ParcelMode::ConstantNp);
  EXPECT_DOUBLE_EQ(s.np, 8.0);
  EXPECT_EQ(s.scaling, CollisionScaling::None);
  EXPECT_EQ(s.seed, 12345679u);
  EXPECT_NEAR(s.uniform_scale_factor(), 2.0, 1e-14);
  EXPECT_EQ(parse("np 27 scaling linear mode constant_np").scaling, CollisionScaling::Linear);
}

TEST(ParcelSettings, ConstantDiameter)
{
  const ParcelSettings s = parse("mode constant_diameter diameter 0.015 distribution 1e-4 0.25 2e-4 0.75 seed 1234567");
  EXPECT_EQ(s.mode, ParcelMode::ConstantDiameter);
  EXPECT_DOUBLE_EQ(s.parcel_diameter, 0.015);
  ASSERT_EQ(s.classes.size(), 2u);
  EXPECT_DOUBLE_EQ(s.classes[1].diameter, 2e-4);
  EXPECT_DOUBLE_EQ(s.classes[1].mass_fraction, 0.75);
  EXPECT_EQ(s.seed, 1234567u);
  EXPECT_EQ(s.uniform_scale_factor(), 0.0);
  const ParcelSettings one = parse("mode constant_diameter diameter 0.004 dp 0.001 scaling linear");
  EXPECT_NEAR(one.uniform_scale_factor(), 4.0, 1e-14);
}

TEST(ParcelSettings, DiameterByType)
{
  // two size classes of one parcel diameter kept as atom types 1 and 2; type 3 (walls) holds no parcels
  const ParcelSettings s = parse("mode constant_diameter diameter 0.005 dp_by_type 0.0015 0.0025 none scaling linear");
  EXPECT_EQ(s.mode, ParcelMode::ConstantDiameter);
  EXPECT_TRUE(s.by_type());
  EXPECT_TRUE(s.classes.empty());
  EXPECT_EQ(s.type_diameters, (std::vector<double>{0.0015, 0.0025, kNoParcels}));
  EXPECT_EQ(s.scaling, CollisionScaling::Linear);
  EXPECT_EQ(s.uniform_scale_factor(), 0.0);
  const double np1 = std::pow(0.005 / 0.0015, 3), np2 = 8.0;
  EXPECT_NEAR(s.pair_scale_factor(1, 1), 0.005 / 0.0015, 1e-14);
  EXPECT_NEAR(s.pair_scale_factor(2, 2), 2.0, 1e-14);
  EXPECT_NEAR(s.pair_scale_factor(1, 2), std::cbrt(0.5 * (np1 + np2)), 1e-14);
  EXPECT_EQ(s.pair_scale_factor(2, 1), s.pair_scale_factor(1, 2));
  EXPECT_NEAR(s.pair_scale_factor(1, 3), 0.005 / 0.0015, 1e-14);  // against the wall: the parcel's own l
  EXPECT_NEAR(s.pair_scale_factor(3, 2), 2.0, 1e-14);
  EXPECT_EQ(s.pair_scale_factor(3, 3), 1.0);
  // the values end at the next keyword, in any order of keywords
  const ParcelSettings t = parse("dp_by_type 0.001 0.002 seed 7 mode constant_diameter diameter 0.004");
  EXPECT_EQ(t.type_diameters, (std::vector<double>{0.001, 0.002}));
  EXPECT_EQ(t.seed, 7u);
  EXPECT_EQ(t.scaling, CollisionScaling::None);
  // one diameter for every type is the uniform case
  const ParcelSettings u = parse("mode constant_diameter diameter 0.004 dp_by_type 0.002 0.002 none scaling linear");
  for (int i = 1; i <= 2; ++i)
    for (int j = 1; j <= 3; ++j) EXPECT_NEAR(u.pair_scale_factor(i, j), 2.0, 1e-14);
}

TEST(ParcelSettings, Errors)
{
  expect_error("", {"'mode' is missing"});
  expect_error("mode", {"'mode' needs a value"});
  expect_error("mode fancy np 2", {"'mode'", "'fancy'", "constant_np, constant_diameter"});
  expect_error("mode constant_np", {"needs keyword 'np'"});
  expect_error("mode constant_np np", {"'np' needs a value"});
  expect_error("mode constant_np np abc", {"'np'", "'abc'", "number"});
  expect_error("mode constant_np np 0.5", {"'np'", "'0.5'", ">= 1"});
  expect_error("mode constant_np np -8", {"'np'", "'-8'", ">= 1"});
  expect_error("mode constant_np np 8 colour red", {"unknown keyword 'colour'", "allowed keywords"});
  expect_error("mode constant_np np 8 np 4", {"'np' given twice"});
  expect_error("mode constant_np np 8 diameter 0.01", {"'diameter'", "not allowed with mode constant_np"});
  expect_error("mode constant_np np 8 scaling cubic", {"'scaling'", "'cubic'", "none, linear"});
  expect_error("mode constant_np np 8 seed 0", {"'seed'", "'0'", "integer"});
  expect_error("mode constant_np np 8 seed 1.5", {"'seed'", "'1.5'"});
  expect_error("mode constant_diameter dp 0.001", {"needs keyword 'diameter'"});
  expect_error("mode constant_diameter diameter 0 dp 0.001", {"'diameter'", "'0'", "> 0"});
  expect_error("mode constant_diameter diameter -0.01 dp 0.001", {"'diameter'", "'-0.01'", "> 0"});
  expect_error("mode constant_diameter diameter 0.01", {"'dp', 'distribution' or 'dp_by_type'"});
  expect_error("mode constant_diameter diameter 0.01 dp 0", {"'dp'", "'0'", "> 0"});
  expect_error("mode constant_diameter diameter 0.01 dp 0.02", {"0.02", "larger than the parcel diameter", "dp <= diameter"});
  expect_error("mode constant_diameter diameter 0.01 np 8 dp 0.001", {"'np' is not allowed"});
  expect_error("mode constant_diameter diameter 0.01 distribution", {"'distribution' needs at least one pair"});
  expect_error("mode constant_diameter diameter 0.01 distribution 0.001", {"'distribution'", "'0.001'", "no mass fraction"});
  expect_error("mode constant_diameter diameter 0.01 distribution 0.001 0.5 0.002 0.4",
               {"'distribution'", "sum to 0.9", "1 within 1e-6"});
  expect_error("mode constant_diameter diameter 0.01 distribution 0.001 0.5 0.002 0.5000011",
               {"'distribution'", "sum to 1.0000011"});
  expect_error("mode constant_diameter diameter 0.01 distribution 0.001 1.2 0.002 -0.2",
               {"'distribution'", "-0.2", "mass fractions > 0"});
  expect_error("mode constant_diameter diameter 0.01 distribution -0.001 1", {"'distribution'", "-0.001", "diameters > 0"});
  expect_error("mode constant_diameter diameter 0.01 distribution 0.001 0.5 0.001 0.5", {"twice", "distinct"});
  expect_error("mode constant_diameter diameter 0.01 dp 0.001 distribution 0.001 1", {"exclude each other"});
  expect_error("mode constant_diameter diameter 0.01 distribution 0.001 0.5 0.002 0.5 scaling linear",
               {"'scaling' linear", "2 particle diameters", "scaling none", "dp_by_type"});
  // dp_by_type
  const std::string cd = "mode constant_diameter diameter 0.005 ";
  expect_error(cd + "dp_by_type", {"'dp_by_type' needs one value per atom type", "none"});
  expect_error(cd + "dp_by_type scaling none", {"'dp_by_type' needs one value per atom type"});
  expect_error(cd + "dp_by_type 0.0015 abc 0.0025", {"'dp_by_type' got 'abc' for atom type 2", "> 0", "none"});
  expect_error(cd + "dp_by_type -0.001 0.0025", {"'dp_by_type' got '-0.001' for atom type 1", "> 0 and <= diameter"});
  expect_error(cd + "dp_by_type 0.0015 0", {"'dp_by_type' got '0' for atom type 2"});
  expect_error(cd + "dp_by_type 0.0015 0.006 none", {"'dp_by_type' got 0.006 for atom type 2", "larger than the parcel "
                                                     "diameter 0.005", "<= diameter"});
  expect_error(cd + "dp_by_type none none", {"'dp_by_type' got none for every atom type", "at least one type"});
  expect_error(cd + "dp_by_type 0.0015 0.0025 dp_by_type 0.0015 0.0025", {"'dp_by_type' given twice"});
  expect_error(cd + "dp 0.0015 dp_by_type 0.0015 0.0025", {"'dp', 'distribution' and 'dp_by_type' exclude each other"});
  expect_error(cd + "distribution 0.0015 1 dp_by_type 0.0015 0.0025", {"exclude each other"});
  expect_error("mode constant_np np 8 dp_by_type 0.001 0.002", {"'dp_by_type' is not allowed with mode constant_np"});
  // within 1e-6 is accepted
  EXPECT_NO_THROW(parse("mode constant_diameter diameter 0.01 distribution 0.001 0.5 0.002 0.5000009"));
  // shear_stress: the particles' restitution, with scaling linear, for parcels no coarser than it allows
  expect_error("mode constant_np np 8 shear_stress 0.97", {"'shear_stress'", "scaling linear only"});
  expect_error("mode constant_np np 8 scaling linear shear_stress 1", {"'shear_stress' got '1'", "> 0 and < 1"});
  expect_error("mode constant_np np 8 scaling linear shear_stress 0", {"'shear_stress' got '0'"});
  expect_error("mode constant_np np 8 scaling linear shear_stress", {"'shear_stress' needs a value"});
  expect_error("mode constant_np np 27 scaling linear shear_stress 0.97",
               {"'shear_stress' 0.97", "l = D/dp <= 2.028", "the parcels have l = 3;", "fewer particles per parcel"});
  expect_error("mode constant_np np 8 scaling linear shear_stress 0.9", {"l = D/dp <= 1.515", "the parcels have l = 2;"});
  expect_error(cd + "dp_by_type 0.0015 0.0025 none scaling linear shear_stress 0.97",
               {"l = D/dp <= 2.028", "the parcels have l = 3.333"});  // types 1-1: 5 / 1.5 mm
}

TEST(ParcelSettings, ShearStress)
{
  const ParcelSettings s = parse("mode constant_np np 8 scaling linear shear_stress 0.97");
  EXPECT_EQ(s.shear_stress_restitution, 0.97);
  EXPECT_NEAR(s.largest_parcel_pair_scale_factor(), 2.0, 1e-14);
  EXPECT_EQ(parse("mode constant_np np 8 scaling linear").shear_stress_restitution, 0.0);
  // dp_by_type: the largest l of two parcel types, the wall type (none) left out
  const ParcelSettings t =
      parse("mode constant_diameter diameter 0.004 dp_by_type 0.002 0.0025 none scaling linear shear_stress 0.97");
  EXPECT_NEAR(t.largest_parcel_pair_scale_factor(), 2.0, 1e-14);
}

TEST(ReinjectSettings, AcceptedFormsAndDefaults)
{
  const ReinjectSettings s = parse_reinject_settings(split("outlet top return bottom velocity 0 -0.5 1e-1"));
  EXPECT_EQ(s.outlet, "top");
  EXPECT_EQ(s.return_region, "bottom");
  EXPECT_EQ(s.velocity, (std::array<double, 3>{0.0, -0.5, 0.1}));
  EXPECT_EQ(s.every, 1);
  EXPECT_EQ(s.seed, 12345679u);
  EXPECT_EQ(s.attempts, 100);
  EXPECT_FALSE(s.lowest);
  const ReinjectSettings t = parse_reinject_settings(
      split("attempts 7 seed 4294967295 every 25 velocity 1 2 3 placement lowest return b outlet a"));
  EXPECT_TRUE(t.lowest);
  EXPECT_FALSE(parse_reinject_settings(split("outlet a return b velocity 0 0 0 placement random")).lowest);
  EXPECT_EQ(t.every, 25);
  EXPECT_EQ(t.seed, 4294967295u);
  EXPECT_EQ(t.attempts, 7);
  EXPECT_EQ(t.outlet, "a");
}

TEST(ReinjectSettings, Errors)
{
  const std::string base = "outlet top return bottom velocity 0 0 1 ";
  expect_reinject_error("return bottom velocity 0 0 1", {"'outlet' is missing", "outlet REGION_ID"});
  expect_reinject_error("outlet top velocity 0 0 1", {"'return' is missing"});
  expect_reinject_error("outlet top return bottom", {"'velocity' is missing", "velocity vx vy vz"});
  expect_reinject_error("outlet top return bottom velocity 0 1", {"'velocity' needs three numbers"});
  expect_reinject_error("outlet top return bottom velocity 0 up 1", {"'velocity' got 'up'", "three numbers"});
  expect_reinject_error(base + "every -5", {"'every' got '-5'", "an integer >= 1"});
  expect_reinject_error(base + "every 0", {"'every' got '0'"});
  expect_reinject_error(base + "every 2.5", {"'every' got '2.5'"});
  expect_reinject_error(base + "every", {"'every' needs an integer >= 1"});
  expect_reinject_error(base + "seed 0", {"'seed' got '0'", "1 to 4294967295"});
  expect_reinject_error(base + "attempts x", {"'attempts' got 'x'", "an integer >= 1"});
  expect_reinject_error(base + "every 2 every 3", {"'every' given twice"});
  expect_reinject_error(base + "placement top", {"'placement' got 'top'", "random, lowest"});
  expect_reinject_error(base + "placement", {"'placement' needs random or lowest"});
  expect_reinject_error(base + "colour red",
                        {"unknown keyword 'colour'", "outlet, return, velocity, every, seed, attempts, placement"});
  expect_reinject_error("outlet same return same velocity 0 0 1", {"'outlet' and 'return' both got 'same'", "two different"});
}
