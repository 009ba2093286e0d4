#pragma once
// Beetstra - van der Hoef - Kuipers (BVK) drag law with the polydisperse correction.
// References: R. Beetstra, M.A. van der Hoef, J.A.M. Kuipers, "Drag force of intermediate Reynolds
// number flow past mono- and bidisperse arrays of spheres", AIChE J. 53 (2007) 489-501;
// M.A. van der Hoef, R. Beetstra, J.A.M. Kuipers, J. Fluid Mech. 528 (2005) 233-254 (polydisperse
// Stokes correction); open implementation: MFiX DRAG_BVK (model/drag_gs.f).
// Monodisperse, with phi = a_s, eps = a_g, Re = eps rho_g |u - v| <d> / mu:
//   F = 10 phi / eps^2 + eps^2 (1 + 1.5 sqrt(phi))
//     + 0.413 Re / (24 eps^2) (1/eps + 3 eps phi + 8.4 Re^-0.343) / (1 + 10^(3 phi) Re^-(1 + 4 phi)/2)
// F is the drag on one particle normalised by 3 pi mu d eps |u - v| (Stokes drag at the superficial
// slip), so beta = 18 mu eps phi F / d^2 (Carman-Kozeny 180 phi^2 mu/(eps d^2) at Re -> 0).
// Polydisperse (van der Hoef 2005, Beetstra 2007): particle i of diameter d_i in a mixture of Sauter
// mean <d>, y_i = d_i / <d>, Re and F evaluated with <d>:
//   F_i = (eps y_i + phi y_i^2) F(phi, Re<d>),  F_i = drag on particle i / (3 pi mu <d> eps |u - v|),
//   K_i = beta_i / a_s = 18 mu eps F_i <d> / d_i^3 = 18 mu eps F (eps + phi y_i) / d_i^2.
// The normalisation with <d> is the one for which the factor has the right limits: dilute (phi -> 0)
// each particle feels its own Stokes drag 3 pi mu d_i U, dense (phi y^2 term) drag scales with the
// surface d_i^2 (Carman-Kozeny of the Sauter mean), and y_i = 1 gives the monodisperse law exactly.
// (MFiX's DES model-A branch instead scales the d_i-normalised law by 1/y_i; Beetstra 2007 also has a
// term 0.064 eps y_i^3 for finite Re that does not reduce to 1 at y_i = 1; neither is used here.)
#include "coupling/drag/drag_input.hpp"

namespace parcelflow::coupling {

class BeetstraDrag {
 public:
  static constexpr const char* typeName = "BeetstraVanDerHoefKuipers";
  static constexpr bool usesMeanDiameter = true;  // reads DragInput::dMean: the coupler supplies it
  static const char* reference();

  // Monodisperse normalised drag F(phi, Re) (see header comment).
  static double normalisedDrag(double phi, double re) noexcept {
    const double eps = 1.0 - phi;
    const double f0 = 10.0 * phi / (eps * eps) + eps * eps * (1.0 + 1.5 * std::sqrt(phi));
    if (!(re > 0.0)) return f0;
    // 0.413 Re/(24 eps^2) (A + 8.4 Re^-0.343) / (1 + 10^(3phi) Re^-q), multiplied through by Re^q.
    const double q = 0.5 + 2.0 * phi;
    const double rq = std::pow(re, q);
    const double num = re * (1.0 / eps + 3.0 * eps * phi) + 8.4 * std::pow(re, 0.657);
    return f0 + 0.413 / (24.0 * eps * eps) * num * rq / (rq + std::pow(10.0, 3.0 * phi));
  }

  // K = beta / a_s [kg/(m^3 s)] for the particle of diameter in.dp in a mixture of Sauter mean in.dMean.
  double coefficient(const DragInput& in) const noexcept {
    const double dMean = in.dMean > 0.0 ? in.dMean : in.dp;
    const double phi = 1.0 - in.alphaG;
    const double re = drag_detail::reynolds(in, dMean);
    // (eps y + phi y^2) <d> / d_i^3 = (eps + phi y) / d_i^2; exactly 1/d^2 when monodisperse
    const double factor = in.dMean > 0.0 ? in.alphaG + phi * (in.dp / dMean) : 1.0;
    return 18.0 * in.muG * in.alphaG * normalisedDrag(phi, re) * factor / (in.dp * in.dp);
  }
};

}  // namespace parcelflow::coupling
