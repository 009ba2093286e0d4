#include "liggghts_plugins/parcel_settings.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

#include "liggghts_plugins/parcel_math.h"

namespace parcelflow::plugins {
namespace {

[[noreturn]] void fail(const std::string& what) { throw ArgumentError("fix parcel: " + what); }

std::string quoted(const std::string& s) { return "'" + s + "'"; }

const std::vector<std::string> kKeywordList = {"mode", "np", "diameter", "dp", "distribution", "dp_by_type", "seed",
                                                "scaling", "shear_stress"};
const std::set<std::string> kKeywordSet(kKeywordList.begin(), kKeywordList.end());

std::string keyword_names()
{
  std::string names;
  for (const std::string& k : kKeywordList) names += (names.empty() ? "" : ", ") + k;
  return names;
}
const std::string kTypeDiameterAllowed =
    "a particle diameter > 0 and <= diameter, or none (an atom type without parcels, e.g. the walls)";

// shear_stress lowers the parcel-parcel restitution of the linearly scaled contacts, as far as 0 at most.
void check_shear_stress(const ParcelSettings& s)
{
  if (s.scaling != CollisionScaling::Linear)
    fail("keyword 'shear_stress' changes the linearly scaled contacts; allowed with scaling linear only");
  const double e = s.shear_stress_restitution, l = s.largest_parcel_pair_scale_factor();
  const double limit = largest_shear_stress_scale_factor(e);
  if (std::isnan(shear_stress_restitution(e, l))) {
    std::ostringstream msg;
    msg.precision(4);
    msg << "keyword 'shear_stress' " << e << " needs 1 - e'^2 = l^4 (1 - " << e << "^2) <= 1, i.e. l = D/dp <= "
        << limit << ", but the parcels have l = " << l << "; allowed: fewer particles per parcel, or no "
        << "shear_stress";
    fail(msg.str());
  }
}

}  // namespace

bool is_number(const std::string& token)
{
  if (token.empty()) return false;
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  return end != begin && *end == '\0' && errno == 0 && std::isfinite(v);
}

double parse_number(const std::string& keyword, const std::string& token)
{
  if (!is_number(token))
    fail("keyword '" + keyword + "' needs a number, got " + quoted(token));
  return std::strtod(token.c_str(), nullptr);
}

double ParcelSettings::uniform_scale_factor() const
{
  if (mode == ParcelMode::ConstantNp) return std::cbrt(np);
  if (classes.size() == 1) return parcel_diameter / classes.front().diameter;
  return 0.0;
}

double ParcelSettings::pair_scale_factor(int type_i, int type_j) const
{
  if (!by_type()) return uniform_scale_factor();
  const double dp_i = type_diameters.at(type_i - 1), dp_j = type_diameters.at(type_j - 1);
  if (dp_i == kNoParcels && dp_j == kNoParcels) return 1.0;
  if (dp_j == kNoParcels) return parcel_diameter / dp_i;
  if (dp_i == kNoParcels) return parcel_diameter / dp_j;
  return equal_mass_pair_scale_factor(particles_per_parcel(parcel_diameter, dp_i),
                                      particles_per_parcel(parcel_diameter, dp_j));
}

double ParcelSettings::largest_parcel_pair_scale_factor() const
{
  if (!by_type()) return uniform_scale_factor();
  double largest = 0.0;
  const int ntypes = static_cast<int>(type_diameters.size());
  for (int i = 1; i <= ntypes; ++i)
    for (int j = i; j <= ntypes; ++j)
      if (type_diameters[i - 1] != kNoParcels && type_diameters[j - 1] != kNoParcels)
        largest = std::max(largest, pair_scale_factor(i, j));
  return largest;
}

const char* to_string(ParcelMode mode)
{
  return mode == ParcelMode::ConstantNp ? "constant_np" : "constant_diameter";
}

const char* to_string(CollisionScaling scaling)
{
  return scaling == CollisionScaling::None ? "none" : "linear";
}

ParcelSettings parse_parcel_settings(const std::vector<std::string>& args)
{
  ParcelSettings s;
  std::set<std::string> seen;
  bool have_mode = false, have_np = false, have_diameter = false, have_dp = false, have_dist = false,
       have_by_type = false;
  std::size_t i = 0;
  auto value_of = [&](const std::string& key, const char* allowed) -> const std::string& {
    if (i + 1 >= args.size()) fail("keyword '" + key + "' needs a value (" + allowed + ")");
    return args[i + 1];
  };
  while (i < args.size()) {
    const std::string& key = args[i];
    if (seen.count(key) && key != "") fail("keyword '" + key + "' given twice");
    seen.insert(key);
    if (key == "mode") {
      const std::string& v = value_of(key, "constant_np or constant_diameter");
      if (v == "constant_np") s.mode = ParcelMode::ConstantNp;
      else if (v == "constant_diameter") s.mode = ParcelMode::ConstantDiameter;
      else fail("keyword 'mode' got " + quoted(v) + "; allowed: constant_np, constant_diameter");
      have_mode = true;
      i += 2;
    } else if (key == "np") {
      const double v = parse_number(key, value_of(key, "a number >= 1"));
      if (!(v >= 1.0)) fail("keyword 'np' got " + quoted(args[i + 1]) + "; allowed: a number >= 1");
      s.np = v;
      have_np = true;
      i += 2;
    } else if (key == "diameter") {
      const double v = parse_number(key, value_of(key, "a parcel diameter > 0"));
      if (!(v > 0.0)) fail("keyword 'diameter' got " + quoted(args[i + 1]) + "; allowed: a parcel diameter > 0");
      s.parcel_diameter = v;
      have_diameter = true;
      i += 2;
    } else if (key == "dp") {
      const double v = parse_number(key, value_of(key, "a particle diameter > 0"));
      if (!(v > 0.0)) fail("keyword 'dp' got " + quoted(args[i + 1]) + "; allowed: a particle diameter > 0");
      s.classes = {SizeClass{v, 1.0}};
      have_dp = true;
      i += 2;
    } else if (key == "distribution") {
      std::size_t j = i + 1;
      std::vector<SizeClass> classes;
      while (j + 1 < args.size() && is_number(args[j]) && is_number(args[j + 1])) {
        classes.push_back({std::strtod(args[j].c_str(), nullptr), std::strtod(args[j + 1].c_str(), nullptr)});
        j += 2;
      }
      if (j < args.size() && is_number(args[j]))
        fail("keyword 'distribution' needs pairs 'diameter mass_fraction'; the diameter " + quoted(args[j]) +
             " has no mass fraction");
      if (classes.empty())
        fail("keyword 'distribution' needs at least one pair 'diameter mass_fraction'" +
             std::string(j < args.size() ? ", got " + quoted(args[j]) : ""));
      double sum = 0.0;
      std::set<double> diameters;
      for (const SizeClass& c : classes) {
        std::ostringstream v;
        v << c.diameter << " " << c.mass_fraction;
        if (!(c.diameter > 0.0))
          fail("keyword 'distribution' got diameter " + quoted(v.str().substr(0, v.str().find(' '))) +
               "; allowed: diameters > 0");
        if (!(c.mass_fraction > 0.0))
          fail("keyword 'distribution' got the pair " + quoted(v.str()) + "; allowed: mass fractions > 0");
        if (!diameters.insert(c.diameter).second)
          fail("keyword 'distribution' lists the diameter " + quoted(v.str().substr(0, v.str().find(' '))) +
               " twice; allowed: distinct diameters");
        sum += c.mass_fraction;
      }
      if (std::fabs(sum - 1.0) > 1e-6) {
        std::ostringstream msg;
        msg.precision(12);
        msg << "keyword 'distribution': the mass fractions sum to " << sum
            << "; allowed: a sum of 1 within 1e-6";
        fail(msg.str());
      }
      if (classes.size() > 65535) fail("keyword 'distribution': at most 65535 size classes are allowed");
      s.classes = classes;
      have_dist = true;
      i = j;
    } else if (key == "dp_by_type") {
      // the values run up to the next keyword, so that a bad value is named as one
      std::size_t j = i + 1;
      std::vector<double> diameters;
      for (; j < args.size() && !kKeywordSet.count(args[j]); ++j) {
        const std::string type = std::to_string(diameters.size() + 1);
        if (args[j] == "none") {
          diameters.push_back(kNoParcels);
        } else if (is_number(args[j]) && std::strtod(args[j].c_str(), nullptr) > 0.0) {
          diameters.push_back(std::strtod(args[j].c_str(), nullptr));
        } else {
          fail("keyword 'dp_by_type' got " + quoted(args[j]) + " for atom type " + type + "; allowed: " +
               kTypeDiameterAllowed);
        }
      }
      if (diameters.empty())
        fail("keyword 'dp_by_type' needs one value per atom type 1, 2, ...; allowed per type: " + kTypeDiameterAllowed);
      if (std::all_of(diameters.begin(), diameters.end(), [](double d) { return d == kNoParcels; }))
        fail("keyword 'dp_by_type' got none for every atom type; allowed: a particle diameter for at least one type");
      s.type_diameters = diameters;
      have_by_type = true;
      i = j;
    } else if (key == "seed") {
      const double v = parse_number(key, value_of(key, "a positive integer"));
      if (!(v >= 1.0 && v <= 4294967295.0 && v == std::floor(v)))
        fail("keyword 'seed' got " + quoted(args[i + 1]) + "; allowed: an integer from 1 to 4294967295");
      s.seed = static_cast<std::uint32_t>(v);
      i += 2;
    } else if (key == "scaling") {
      const std::string& v = value_of(key, "none or linear");
      if (v == "none") s.scaling = CollisionScaling::None;
      else if (v == "linear") s.scaling = CollisionScaling::Linear;
      else fail("keyword 'scaling' got " + quoted(v) + "; allowed: none, linear");
      i += 2;
    } else if (key == "shear_stress") {
      const double v = parse_number(key, value_of(key, "the particles' restitution coefficient"));
      if (!(v > 0.0 && v < 1.0))
        fail("keyword 'shear_stress' got " + quoted(args[i + 1]) +
             "; allowed: the particles' restitution coefficient, > 0 and < 1");
      s.shear_stress_restitution = v;
      i += 2;
    } else {
      fail("unknown keyword " + quoted(key) + "; allowed keywords: " + keyword_names());
    }
  }

  if (!have_mode) fail("keyword 'mode' is missing; allowed: mode constant_np | mode constant_diameter");
  if (s.mode == ParcelMode::ConstantNp) {
    if (!have_np) fail("mode constant_np needs keyword 'np' (real particles per parcel, >= 1)");
    if (have_diameter || have_dp || have_dist || have_by_type)
      fail(std::string("keyword '") +
           (have_diameter ? "diameter" : have_dp ? "dp" : have_dist ? "distribution" : "dp_by_type") +
           "' is not allowed with mode constant_np (dp follows from the inserted diameter and np); "
           "use mode constant_diameter");
  } else {
    if (have_np)
      fail("keyword 'np' is not allowed with mode constant_diameter (np = (D/dp)^3 per parcel)");
    if (!have_diameter) fail("mode constant_diameter needs keyword 'diameter' (the parcel diameter D)");
    if (int(have_dp) + int(have_dist) + int(have_by_type) > 1)
      fail("keywords 'dp', 'distribution' and 'dp_by_type' exclude each other; give one");
    if (!have_dp && !have_dist && !have_by_type)
      fail("mode constant_diameter needs keyword 'dp', 'distribution' or 'dp_by_type' (real particle diameters)");
    for (const SizeClass& c : s.classes)
      if (c.diameter > s.parcel_diameter * (1.0 + 1e-12)) {
        std::ostringstream msg;
        msg << "particle diameter " << c.diameter << " is larger than the parcel diameter " << s.parcel_diameter
            << " (keyword '" << (have_dp ? "dp" : "distribution") << "'); allowed: dp <= diameter (np >= 1)";
        fail(msg.str());
      }
    for (std::size_t t = 0; t < s.type_diameters.size(); ++t)
      if (s.type_diameters[t] > s.parcel_diameter * (1.0 + 1e-12)) {
        std::ostringstream msg;
        msg << "keyword 'dp_by_type' got " << s.type_diameters[t] << " for atom type " << t + 1
            << ", larger than the parcel diameter " << s.parcel_diameter << "; allowed: " << kTypeDiameterAllowed;
        fail(msg.str());
      }
    if (s.scaling == CollisionScaling::Linear && s.classes.size() > 1)
      fail("keyword 'scaling' linear needs one l = D/dp per type pair, but the distribution has " +
           std::to_string(s.classes.size()) +
           " particle diameters; allowed: scaling none, or a single size (dp), one size per atom type "
           "(dp_by_type), or mode constant_np");
  }
  if (s.shear_stress_restitution > 0.0) check_shear_stress(s);
  return s;
}

}  // namespace parcelflow::plugins
