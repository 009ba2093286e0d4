#include "coupling/heat/nusselt_correlation.hpp"

#include <cstddef>

#include "cfd/base/config_error.hpp"
#include "cfd/base/internal_error.hpp"

namespace parcelflow::coupling {
namespace {

struct Entry {
  std::string name;
  NusseltCorrelation (*make)();
};

template <std::size_t I>
NusseltCorrelation makeAlternative() {
  return NusseltCorrelation(std::in_place_index<I>);
}

template <std::size_t... I>
std::vector<Entry> buildRegistry(std::index_sequence<I...>) {
  std::vector<Entry> entries{
      Entry{std::variant_alternative_t<I, NusseltCorrelation>::typeName, &makeAlternative<I>}...};
  for (std::size_t a = 0; a < entries.size(); ++a)
    for (std::size_t b = a + 1; b < entries.size(); ++b)
      PARCELFLOW_ASSERT(entries[a].name != entries[b].name,
                        "Nusselt correlation registry: duplicate name '" + entries[a].name + "'");
  return entries;
}

const std::vector<Entry>& registry() {
  static const std::vector<Entry> entries =
      buildRegistry(std::make_index_sequence<std::variant_size_v<NusseltCorrelation>>{});
  return entries;
}

}  // namespace

std::vector<std::string> nusseltCorrelationNames() {
  std::vector<std::string> names;
  for (const Entry& e : registry()) names.push_back(e.name);
  return names;
}

NusseltCorrelation makeNusseltCorrelation(const std::string& name, const std::string& key) {
  for (const Entry& e : registry())
    if (e.name == name) return e.make();
  std::string valid;
  for (const Entry& e : registry()) valid += (valid.empty() ? "" : ", ") + e.name;
  throw cfd::ConfigError(key, name, "one of " + valid);
}

std::string nusseltCorrelationName(const NusseltCorrelation& correlation) {
  return visitNusseltCorrelation(correlation, [](const auto& c) { return std::string(c.typeName); });
}

std::string nusseltCorrelationReference(const NusseltCorrelation& correlation) {
  return visitNusseltCorrelation(correlation, [](const auto& c) { return std::string(c.reference()); });
}

double nusseltNumber(const NusseltCorrelation& correlation, const NusseltInput& in) {
  return visitNusseltCorrelation(correlation, [&](const auto& c) { return c.nusselt(in); });
}

}  // namespace parcelflow::coupling
