#pragma once
// Ranz & Marshall's Nusselt number for a single sphere.
// Reference: W.E. Ranz, W.R. Marshall, "Evaporation from drops", Chem. Eng. Prog. 48 (1952) 141-146:
//   Nu = 2 + 0.6 Re^(1/2) Pr^(1/3),  Re = a rho_g |u - v| d_p / mu_g (as for Gunn and the drag laws).
// A single-sphere correlation (measured for Re below about 200): it has no gas-fraction dependence, so in
// a dense bed it under-predicts the transfer that Gunn's correlation gives. Only Re above 200 is counted
// as outside its range (it states no gas-fraction range: it knows no neighbours).
#include <cmath>

#include "coupling/heat/nusselt_input.hpp"

namespace parcelflow::coupling {

class RanzMarshallNusselt {
 public:
  static constexpr const char* typeName = "RanzMarshall";
  static constexpr double minAlphaG = 0.0;
  static constexpr double maxReynolds = 200.0;
  static const char* reference();

  double nusselt(const NusseltInput& in) const noexcept {
    return 2.0 + 0.6 * std::sqrt(in.reynolds) * std::cbrt(in.prandtl);
  }
};

}  // namespace parcelflow::coupling
