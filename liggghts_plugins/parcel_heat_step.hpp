// One DEM step of a parcel's temperature, M c dT/dt = H (T_g - T) + Q, implicit Euler:
//     T_new = (M c T + dt (H T_g + Q)) / (M c + dt H).
// Implicit Euler rather than the exact exponential of the convective part because (1) it is the
// discretisation the gas side uses for the same exchange (implicit source), so both sides see one
// scheme; (2) it takes the other heat Q (contact conduction) in the same formula, with no splitting;
// (3) it is L-stable and monotone: for dt H/(M c) -> infinity T_new -> T_g + Q/H, never beyond, so fine
// particles whose thermal response time M c/H is far below the DEM step neither limit the step nor
// overshoot. Its error is first order, dt H/(2 M c) relative per response time.
#pragma once

namespace parcelflow::plugins {

// heat_capacity = M c [J/K] > 0, conductance = H [W/K] >= 0, source = Q [W].
inline double implicit_heat_step(double heat_capacity, double temperature, double dt, double conductance,
                                 double gas_temperature, double source)
{
  return (heat_capacity * temperature + dt * (conductance * gas_temperature + source)) /
         (heat_capacity + dt * conductance);
}

}  // namespace parcelflow::plugins
