#pragma once
// Run-time selection of a gas-particle Nusselt correlation by name, without a virtual call per particle
// (the pattern of the drag laws).
//
// Every correlation is a small class with `static constexpr const char* typeName`, `static const char*
// reference()`, its stated range (`minAlphaG`, `maxReynolds`) and an inline
// `double nusselt(const NusseltInput&) const`. A NusseltCorrelation holds one of them; the registry is
// built from the alternatives of the variant, so adding a correlation means: write the class, add it to
// the list below. makeNusseltCorrelation("Gunn") selects one at run time; an unknown name throws
// cfd::ConfigError listing the valid names. Hot loops visit the variant ONCE (forEachParcelHeat in
// parcel_heat_transfer.hpp).
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "coupling/heat/gunn_nusselt.hpp"
#include "coupling/heat/ranz_marshall_nusselt.hpp"

namespace parcelflow::coupling {

using NusseltCorrelation = std::variant<GunnNusselt, RanzMarshallNusselt>;

// Registered names, in registry order.
std::vector<std::string> nusseltCorrelationNames();

// The correlation registered under `name` (exact, case-sensitive); throws cfd::ConfigError naming `key`
// (the case key it came from), the value and the valid names otherwise.
NusseltCorrelation makeNusseltCorrelation(const std::string& name, const std::string& key = "heat.correlation");

std::string nusseltCorrelationName(const NusseltCorrelation& correlation);
std::string nusseltCorrelationReference(const NusseltCorrelation& correlation);

template <class Fn>
decltype(auto) visitNusseltCorrelation(const NusseltCorrelation& correlation, Fn&& fn) {
  return std::visit(std::forward<Fn>(fn), correlation);
}

// One evaluation (one std::visit: for tests and diagnostics, not for particle loops).
double nusseltNumber(const NusseltCorrelation& correlation, const NusseltInput& in);

}  // namespace parcelflow::coupling
