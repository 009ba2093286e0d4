#pragma once
// Gunn's Nusselt number for particles in fixed and fluidised beds.
// Reference: D.J. Gunn, "Transfer of heat or mass to particles in fixed and fluidised beds",
// Int. J. Heat Mass Transfer 21 (1978) 467-476:
//   Nu = (7 - 10 a + 5 a^2)(1 + 0.7 Re^0.2 Pr^(1/3)) + (1.33 - 2.4 a + 1.2 a^2) Re^0.7 Pr^(1/3),
//   a = gas fraction, Re = a rho_g |u - v| d_p / mu_g (superficial slip).
// Valid for 0.35 <= a <= 1 and Re up to 1e5; at a = 1, Re = 0 it is the conduction limit Nu = 2.
#include <cmath>

#include "coupling/heat/nusselt_input.hpp"

namespace parcelflow::coupling {

class GunnNusselt {
 public:
  static constexpr const char* typeName = "Gunn";
  static constexpr double minAlphaG = 0.35;
  static constexpr double maxReynolds = 1.0e5;
  static const char* reference();

  double nusselt(const NusseltInput& in) const noexcept {
    const double a = in.alphaG;
    const double pr3 = std::cbrt(in.prandtl);
    return (7.0 - 10.0 * a + 5.0 * a * a) * (1.0 + 0.7 * std::pow(in.reynolds, 0.2) * pr3) +
           (1.33 - 2.4 * a + 1.2 * a * a) * std::pow(in.reynolds, 0.7) * pr3;
  }
};

}  // namespace parcelflow::coupling
