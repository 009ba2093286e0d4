#include "liggghts_plugins/reinject_settings.h"

#include <cmath>
#include <cstdlib>
#include <set>

#include "liggghts_plugins/parcel_settings.h"

namespace parcelflow::plugins {
namespace {

[[noreturn]] void fail(const std::string& what) { throw ArgumentError("fix parcel/reinject: " + what); }

const std::string kKeywords = "outlet, return, velocity, every, seed, attempts, placement";

// a whole number in [lo, hi] or an error naming the keyword and what is allowed
double whole_number(const std::string& key, const std::string& token, double lo, double hi, const std::string& allowed)
{
  const double v = is_number(token) ? std::strtod(token.c_str(), nullptr) : lo - 1.0;
  if (!(v >= lo && v <= hi && v == std::floor(v))) fail("keyword '" + key + "' got '" + token + "'; allowed: " + allowed);
  return v;
}

}  // namespace

ReinjectSettings parse_reinject_settings(const std::vector<std::string>& args)
{
  ReinjectSettings s;
  std::set<std::string> seen;
  std::size_t i = 0;
  auto value = [&](const std::string& key, std::size_t k, const std::string& allowed) -> const std::string& {
    if (i + k >= args.size()) fail("keyword '" + key + "' needs " + allowed);
    return args[i + k];
  };
  while (i < args.size()) {
    const std::string& key = args[i];
    if (!seen.insert(key).second) fail("keyword '" + key + "' given twice");
    if (key == "outlet" || key == "return") {
      (key == "outlet" ? s.outlet : s.return_region) = value(key, 1, "a region ID");
      i += 2;
    } else if (key == "velocity") {
      for (int k = 0; k < 3; ++k) {
        const std::string& v = value(key, k + 1, "three numbers vx vy vz");
        if (!is_number(v)) fail("keyword 'velocity' got '" + v + "'; allowed: three numbers vx vy vz");
        s.velocity[k] = std::strtod(v.c_str(), nullptr);
      }
      i += 4;
    } else if (key == "every") {
      s.every = static_cast<long>(whole_number(key, value(key, 1, "an integer >= 1"), 1, 1e9, "an integer >= 1"));
      i += 2;
    } else if (key == "seed") {
      s.seed = static_cast<std::uint32_t>(whole_number(key, value(key, 1, "a positive integer"), 1, 4294967295.0,
                                                       "an integer from 1 to 4294967295"));
      i += 2;
    } else if (key == "attempts") {
      s.attempts = static_cast<int>(whole_number(key, value(key, 1, "an integer >= 1"), 1, 1e9, "an integer >= 1"));
      i += 2;
    } else if (key == "placement") {
      const std::string& v = value(key, 1, "random or lowest");
      if (v != "random" && v != "lowest") fail("keyword 'placement' got '" + v + "'; allowed: random, lowest");
      s.lowest = v == "lowest";
      i += 2;
    } else {
      fail("unknown keyword '" + key + "'; allowed keywords: " + kKeywords);
    }
  }
  if (s.outlet.empty()) fail("keyword 'outlet' is missing; allowed: outlet REGION_ID");
  if (s.return_region.empty()) fail("keyword 'return' is missing; allowed: return REGION_ID");
  if (!seen.count("velocity")) fail("keyword 'velocity' is missing; allowed: velocity vx vy vz");
  if (s.outlet == s.return_region)
    fail("keywords 'outlet' and 'return' both got '" + s.outlet + "'; allowed: two different regions");
  return s;
}

}  // namespace parcelflow::plugins
