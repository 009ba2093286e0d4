#pragma once
// Run-time selection of a drag law by name (OpenFOAM-like), without a virtual call per particle.
//
// Every law is a small class with `static constexpr const char* typeName`, `static const char*
// reference()` and an inline `double coefficient(const DragInput&) const` returning K = beta / a_s.
// A law that needs per-case constants has a constructor from DragLawContext (drag_input.hpp), the others
// are default-constructed. A law that may bound a correction also has `coefficient(in, bool& clamped)`,
// which forEachParcel calls and counts. A DragLaw holds one of them; the registry is built from the
// alternatives of this variant, so adding a law means: write the class, add it to the list below.
// makeDragLaw("WenYu", context) selects one at run time; an unknown name throws cfd::ConfigError
// listing the valid names.
//
// Hot loops visit the variant ONCE and run a loop templated on the concrete law
// (forEachParcel in parcel_drag.hpp, or visitDragLaw with a generic lambda).
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "coupling/drag/beetstra_drag.hpp"
#include "coupling/drag/di_felice_drag.hpp"
#include "coupling/drag/ergun_drag.hpp"
#include "coupling/drag/gidaspow_blend_drag.hpp"
#include "coupling/drag/gidaspow_drag.hpp"
#include "coupling/drag/radl_sundaresan_drag.hpp"
#include "coupling/drag/wen_yu_drag.hpp"

namespace parcelflow::coupling {

using DragLaw = std::variant<WenYuDrag, GidaspowDrag, GidaspowBlendDrag, ErgunDrag, DiFeliceDrag,
                             BeetstraDrag, RadlSundaresanDrag>;

// Whether a law reads DragInput::dMean (the local Sauter mean): such a law declares
// `static constexpr bool usesMeanDiameter = true`; the others need not mention it.
template <class Law, class = void>
struct UsesMeanDiameter : std::false_type {};
template <class Law>
struct UsesMeanDiameter<Law, std::void_t<decltype(Law::usesMeanDiameter)>> : std::bool_constant<Law::usesMeanDiameter> {};

inline bool usesMeanDiameter(const DragLaw& law) {
  return std::visit([](const auto& l) { return UsesMeanDiameter<std::decay_t<decltype(l)>>::value; }, law);
}

// Registered names, in registry order.
std::vector<std::string> dragLawNames();

// The law registered under `name` (exact, case-sensitive); throws cfd::ConfigError naming the
// valid ones otherwise. Laws that need the context assert its values (the case reader checks them).
DragLaw makeDragLaw(const std::string& name, const DragLawContext& context = {});

std::string dragLawName(const DragLaw& law);
std::string dragLawReference(const DragLaw& law);

// Calls fn(concreteLaw) once; use it to run a loop templated on the concrete law.
template <class Fn>
decltype(auto) visitDragLaw(const DragLaw& law, Fn&& fn) {
  return std::visit(std::forward<Fn>(fn), law);
}

// Single evaluations (one std::visit each: fine for tests and diagnostics, not for particle loops).
double exchangeCoefficientPerSolidVolume(const DragLaw& law, const DragInput& in);  // K = beta / a_s
double exchangeCoefficient(const DragLaw& law, const DragInput& in);                // beta

// Volume of one real particle, pi d^3 / 6.
inline double particleVolume(double dp) noexcept { return 3.14159265358979323846 / 6.0 * dp * dp * dp; }

// Parcel implicit drag coefficient kappa = np V_p beta / a_s = np V_p K [kg/s] from K = beta / a_s.
// (Never computed as beta / a_s: every law provides K directly, so a_s -> 0 is harmless.)
inline double parcelKappa(double np, double dp, double betaOverAlphaS) noexcept {
  return np * particleVolume(dp) * betaOverAlphaS;
}

}  // namespace parcelflow::coupling
