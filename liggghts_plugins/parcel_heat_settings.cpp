#include "liggghts_plugins/parcel_heat_settings.hpp"

#include <cstdlib>
#include <set>

namespace parcelflow::plugins {
namespace {

[[noreturn]] void fail(const std::string& what) { throw ArgumentError("fix parcel/heat: " + what); }

std::string quoted(const std::string& s) { return "'" + s + "'"; }

}  // namespace

ParcelHeatSettings parse_parcel_heat_settings(const std::vector<std::string>& args, int ntypes)
{
  ParcelHeatSettings s;
  std::set<std::string> seen;
  std::size_t i = 0;
  while (i < args.size()) {
    const std::string& key = args[i];
    if (seen.count(key)) fail("keyword '" + key + "' given twice");
    seen.insert(key);
    if (key == "initial_temperature") {
      if (i + 1 >= args.size()) fail("keyword 'initial_temperature' needs a value (a temperature > 0 K)");
      const std::string& v = args[i + 1];
      if (!is_number(v) || !(std::strtod(v.c_str(), nullptr) > 0.0))
        fail("keyword 'initial_temperature' got " + quoted(v) + "; allowed: a temperature > 0 K");
      s.initial_temperature = std::strtod(v.c_str(), nullptr);
      i += 2;
    } else if (key == "heat_capacity") {
      std::size_t j = i + 1;
      for (; j < args.size() && is_number(args[j]); ++j) {
        const double c = std::strtod(args[j].c_str(), nullptr);
        if (!(c > 0.0))
          fail("keyword 'heat_capacity' got " + quoted(args[j]) + " for atom type " + std::to_string(j - i) +
               "; allowed: a specific heat capacity > 0 J/(kg K)");
        s.heat_capacity.push_back(c);
      }
      if (static_cast<int>(s.heat_capacity.size()) != ntypes)
        fail("keyword 'heat_capacity' got " + std::to_string(s.heat_capacity.size()) + " values but the box has " +
             std::to_string(ntypes) + " atom types; allowed: one specific heat capacity > 0 J/(kg K) per atom type 1.." +
             std::to_string(ntypes));
      i = j;
    } else {
      fail("unknown keyword " + quoted(key) + ". allowed keywords: initial_temperature, heat_capacity");
    }
  }
  if (s.heat_capacity.empty())
    fail("keyword 'heat_capacity' is missing; allowed: heat_capacity c_1 ... c_N, one specific heat capacity > 0 "
         "J/(kg K) per atom type");
  return s;
}

}  // namespace parcelflow::plugins
