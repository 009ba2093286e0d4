#include "coupling/drag/drag_law.hpp"

#include <stdexcept>
#include <type_traits>
#include <utility>

#include "cfd/base/internal_error.hpp"
#include "cfd/base/config_error.hpp"

namespace parcelflow::coupling {
namespace {

struct Entry {
  std::string name;
  DragLaw (*make)(const DragLawContext&);
};

template <std::size_t I>
DragLaw makeAlternative(const DragLawContext& context) {
  using Law = std::variant_alternative_t<I, DragLaw>;
  if constexpr (std::is_constructible_v<Law, const DragLawContext&>)
    return DragLaw(std::in_place_index<I>, context);
  else
    return DragLaw(std::in_place_index<I>);
}

template <std::size_t... I>
std::vector<Entry> buildRegistry(std::index_sequence<I...>) {
  std::vector<Entry> entries{
      Entry{std::variant_alternative_t<I, DragLaw>::typeName, &makeAlternative<I>}...};
  for (std::size_t a = 0; a < entries.size(); ++a)
    for (std::size_t b = a + 1; b < entries.size(); ++b)
      PARCELFLOW_ASSERT(entries[a].name != entries[b].name, "drag law registry: duplicate name '" + entries[a].name + "'");
  return entries;
}

const std::vector<Entry>& registry() {
  static const std::vector<Entry> entries =
      buildRegistry(std::make_index_sequence<std::variant_size_v<DragLaw>>{});
  return entries;
}

}  // namespace

std::vector<std::string> dragLawNames() {
  std::vector<std::string> names;
  for (const Entry& e : registry()) names.push_back(e.name);
  return names;
}

DragLaw makeDragLaw(const std::string& name, const DragLawContext& context) {
  for (const Entry& e : registry())
    if (e.name == name) return e.make(context);
  std::string valid;
  for (const Entry& e : registry()) valid += (valid.empty() ? "" : ", ") + e.name;
  throw cfd::ConfigError("coupling.drag", name, "one of " + valid);
}

std::string dragLawName(const DragLaw& law) {
  return visitDragLaw(law, [](const auto& l) { return std::string(l.typeName); });
}

std::string dragLawReference(const DragLaw& law) {
  return visitDragLaw(law, [](const auto& l) { return std::string(l.reference()); });
}

double exchangeCoefficientPerSolidVolume(const DragLaw& law, const DragInput& in) {
  return visitDragLaw(law, [&](const auto& l) { return l.coefficient(in); });
}

double exchangeCoefficient(const DragLaw& law, const DragInput& in) {
  return (1.0 - in.alphaG) * exchangeCoefficientPerSolidVolume(law, in);
}

}  // namespace parcelflow::coupling
