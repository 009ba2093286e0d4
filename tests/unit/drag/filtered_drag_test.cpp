// RadlSundaresanFilteredBVK (radl_sundaresan_drag.hpp) against values computed independently by
// radl_sundaresan_reference.py (python3 + numpy: the correlations typed in again from their sources, the
// terminal velocity by bisection on the force balance, the fits with numpy.polyval), and its limits:
// H -> 0 as the filter size -> 0 and in the dilute limit, H -> h(phi) for a huge filter, the drag stays
// positive, and the clamp beyond dense packing is counted.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cfd/base/internal_error.hpp"
#include "tests/unit/drag/drag_test_context.hpp"
#include "coupling/drag/parcel_drag.hpp"

using namespace parcelflow::coupling;

namespace {

constexpr double kRhoG = 1.2, kMuG = 1.8e-5, kPi = 3.14159265358979323846;

// g = 9.81 m/s^2, particles of 1500 kg/m^3 (the reference script's values)
RadlSundaresanDrag law(double filterSize) { return RadlSundaresanDrag(test::fccContext(filterSize)); }

DragInput input(double alphaG, double slip, double dp, double dMean = 0.0) {
  DragInput in;
  in.alphaG = alphaG;
  in.rhoG = kRhoG;
  in.muG = kMuG;
  in.dp = dp;
  in.slip = slip;
  in.dMean = dMean;
  return in;
}

}  // namespace

TEST(RadlSundaresanDrag, TerminalVelocityMatchesBisection) {
  struct Row {
    double dp, vt;
  };
  const Row rows[] = {
    {1e-05, 0.0045372646524647394},  // Re_t = 0.00302484
    {6e-05, 0.15539136181477514},  // Re_t = 0.621565
    {9.6e-05, 0.35649580097184053},  // Re_t = 2.28157
    {0.00017, 0.82316578639609683},  // Re_t = 9.32921
    {0.00029, 1.5037606641469612},  // Re_t = 29.0727
    {0.001, 4.141611074174774},  // Re_t = 276.107
  };
  const RadlSundaresanDrag l = law(0.05);
  for (const Row& r : rows) EXPECT_NEAR(l.terminalVelocity(input(1.0, 0.0, r.dp)), r.vt, 1e-12 * r.vt) << r.dp;
}

TEST(RadlSundaresanDrag, TerminalReynoldsSolvesTheForceBalance) {
  // Re_t F(0, Re_t) = Re_St with BVK's own F (beetstra_drag.hpp), from far below Stokes to far above Newton.
  for (double log10ReSt = -12.0; log10ReSt <= 16.0; log10ReSt += 0.25) {
    const double reSt = std::pow(10.0, log10ReSt);
    const double reT = RadlSundaresanDrag::terminalReynolds(reSt);
    EXPECT_LE(reT, reSt);
    EXPECT_NEAR(reT * BeetstraDrag::normalisedDrag(0.0, reT) / reSt, 1.0, 1e-12) << reSt;
  }
}

TEST(RadlSundaresanDrag, FitsMatchTheTable) {
  struct Row {
    double phi, h, a;
  };
  const Row rows[] = {
    {0.000, 0, 21.510000000000002},
    {0.010, 0.079699999999999993, 21.510000000000002},
    {0.016, 0.12751999999999999, 2.4647403519999997},
    {0.050, 0.33206503999999998, 3.6019000000000001},
    {0.100, 0.6211352, 4.6299999999999999},
    {0.150, 0.84270159999999994, 4.1156500000000005},
    {0.200, 0.90557991999999998, 3.206896},
    {0.300, 0.94650272000000002, 2.2894912500000002},
    {0.400, 0.92258607999999998, 1.79},
    {0.500, 0.81948719999999997, 1.79},
    {0.550, 0.68000000000000005, 1.79},
    {0.600, 1.7763568394002505e-15, 1.79},
    {0.650, -1.8059999999999987, 1.79},
  };
  for (const Row& r : rows) {
    EXPECT_NEAR(RadlSundaresanDrag::largeFilterCorrection(r.phi), r.h, 1e-13) << r.phi;
    EXPECT_NEAR(RadlSundaresanDrag::halfCorrectionFilterSize(r.phi), r.a, 1e-13) << r.phi;
  }
}

TEST(RadlSundaresanDrag, CoefficientMatchesIndependentValues) {
  struct Row {
    double alphaG, slip, dp, dMean, filterSize, k, h;
  };
  const Row rows[] = {
    {0.99, 0.025252525252525256, 6e-05, 0, 0.0001, 109996.1468547564, 0.0017512165444346734},  // Delta* 0.040627, x 0.48325, Re 0.1
    {0.99, 25.252525252525253, 6e-05, 0, 0.0001, 503497.36054986849, 0.0017512165444346734},  // Delta* 0.040627, x 0.48325, Re 100
    {0.87, 0.028735632183908042, 6e-05, 0, 0.0001, 208728.7099435917, 0.076568463795233702},  // Delta* 0.040627, x 0.48325, Re 0.1
    {0.87, 28.735632183908042, 6e-05, 0, 0.0001, 701252.49262354011, 0.076568463795233702},  // Delta* 0.040627, x 0.48325, Re 100
    {0.70, 0.035714285714285719, 6e-05, 0, 0.0001, 369079.8532909081, 0.16496188382027341},  // Delta* 0.040627, x 0.48325, Re 0.1
    {0.70, 35.714285714285715, 6e-05, 0, 0.0001, 1035746.3791028565, 0.16496188382027341},  // Delta* 0.040627, x 0.48325, Re 100
    {0.55, 0.045454545454545456, 6e-05, 0, 0.0001, 622315.51872845646, 0.18801752295399016},  // Delta* 0.040627, x 0.48325, Re 0.1
    {0.55, 45.454545454545453, 6e-05, 0, 0.0001, 1569946.9045635136, 0.18801752295399016},  // Delta* 0.040627, x 0.48325, Re 100
    {0.38, 0.065789473684210537, 6e-05, 0, 0.0001, 1479194.6128236253, 0},  // Delta* 0.040627, x 0.48325, Re 0.1, h < 0: clamped
    {0.38, 65.78947368421052, 6e-05, 0, 0.0001, 3496868.2515933011, 0},  // Delta* 0.040627, x 0.48325, Re 100, h < 0: clamped
    {0.99, 0.025252525252525256, 6e-05, 0, 0.045, 102197.51865059299, 0.072526160395040534},  // Delta* 18.282, x 217.46, Re 0.1
    {0.99, 25.252525252525253, 6e-05, 0, 0.045, 467799.84905529884, 0.072526160395040534},  // Delta* 18.282, x 217.46, Re 100
    {0.87, 0.028735632183908042, 6e-05, 0, 0.045, 52540.41916351809, 0.76755722778087621},  // Delta* 18.282, x 217.46, Re 0.1
    {0.87, 28.735632183908042, 6e-05, 0, 0.045, 176516.6848003788, 0.76755722778087621},  // Delta* 18.282, x 217.46, Re 100
    {0.70, 0.035714285714285719, 6e-05, 0, 0.045, 28003.909465733366, 0.9366415381456703},  // Delta* 18.282, x 217.46, Re 0.1
    {0.70, 35.714285714285715, 6e-05, 0, 0.045, 78587.188033251688, 0.9366415381456703},  // Delta* 18.282, x 217.46, Re 100
    {0.55, 0.045454545454545456, 6e-05, 0, 0.045, 94091.61140705226, 0.87723150491947499},  // Delta* 18.282, x 217.46, Re 0.1
    {0.55, 45.454545454545453, 6e-05, 0, 0.045, 237369.67764474289, 0.87723150491947499},  // Delta* 18.282, x 217.46, Re 100
    {0.38, 0.065789473684210537, 6e-05, 0, 0.045, 1479194.6128236253, 0},  // Delta* 18.282, x 217.46, Re 0.1, h < 0: clamped
    {0.38, 65.78947368421052, 6e-05, 0, 0.045, 3496868.2515933011, 0},  // Delta* 18.282, x 217.46, Re 100, h < 0: clamped
    {0.99, 0.025252525252525256, 6e-05, 0, 0.075, 101899.04117329484, 0.075234935085077628},  // Delta* 30.47, x 362.44, Re 0.1
    {0.99, 25.252525252525253, 6e-05, 0, 0.075, 466433.59554278589, 0.075234935085077628},  // Delta* 30.47, x 362.44, Re 100
    {0.87, 0.028735632183908042, 6e-05, 0, 0.075, 51134.278973133725, 0.7737780979068728},  // Delta* 30.47, x 362.44, Re 0.1
    {0.87, 28.735632183908042, 6e-05, 0, 0.075, 171792.5655656475, 0.7737780979068728},  // Delta* 30.47, x 362.44, Re 100
    {0.70, 0.035714285714285719, 6e-05, 0, 0.075, 26271.429524917512, 0.94056125029792848},  // Delta* 30.47, x 362.44, Re 0.1
    {0.70, 35.714285714285715, 6e-05, 0, 0.075, 73725.34090296684, 0.94056125029792848},  // Delta* 30.47, x 362.44, Re 100
    {0.55, 0.045454545454545456, 6e-05, 0, 0.075, 91888.846386516714, 0.88010562029004991},  // Delta* 30.47, x 362.44, Re 0.1
    {0.55, 45.454545454545453, 6e-05, 0, 0.075, 231812.65066823977, 0.88010562029004991},  // Delta* 30.47, x 362.44, Re 100
    {0.38, 0.065789473684210537, 6e-05, 0, 0.075, 1479194.6128236253, 0},  // Delta* 30.47, x 362.44, Re 0.1, h < 0: clamped
    {0.38, 65.78947368421052, 6e-05, 0, 0.075, 3496868.2515933011, 0},  // Delta* 30.47, x 362.44, Re 100, h < 0: clamped
    {0.99, 0.0089126559714795012, 0.00017, 0, 0.0001, 13721.955007589802, 0.00029319024635925556},  // Delta* 0.0014478, x 0.07942, Re 0.1
    {0.99, 8.9126559714795004, 0.00017, 0, 0.0001, 62811.001343787189, 0.00029319024635925556},  // Delta* 0.0014478, x 0.07942, Re 100
    {0.87, 0.010141987829614604, 0.00017, 0, 0.0001, 27770.889925142557, 0.013703136130838853},  // Delta* 0.0014478, x 0.07942, Re 0.1
    {0.87, 10.141987829614603, 0.00017, 0, 0.0001, 93300.082138403843, 0.013703136130838853},  // Delta* 0.0014478, x 0.07942, Re 100
    {0.70, 0.012605042016806723, 0.00017, 0, 0.0001, 53310.655591529008, 0.031732565088579467},  // Delta* 0.0014478, x 0.07942, Re 0.1
    {0.70, 12.605042016806722, 0.00017, 0, 0.0001, 149605.34422073755, 0.031732565088579467},  // Delta* 0.0014478, x 0.07942, Re 100
    {0.55, 0.0160427807486631, 0.00017, 0, 0.0001, 91883.071353235573, 0.037575053200851333},  // Delta* 0.0014478, x 0.07942, Re 0.1
    {0.55, 16.042780748663098, 0.00017, 0, 0.0001, 231798.08169904226, 0.037575053200851333},  // Delta* 0.0014478, x 0.07942, Re 100
    {0.38, 0.023219814241486069, 0.00017, 0, 0.0001, 184259.53654550348, 0},  // Delta* 0.0014478, x 0.07942, Re 0.1, h < 0: clamped
    {0.38, 23.219814241486066, 0.00017, 0, 0.0001, 435596.04518117243, 0},  // Delta* 0.0014478, x 0.07942, Re 100, h < 0: clamped
    {0.99, 0.0089126559714795012, 0.00017, 0, 0.045, 13043.048032181065, 0.049754650084258438},  // Delta* 0.65149, x 35.739, Re 0.1
    {0.99, 8.9126559714795004, 0.00017, 0, 0.045, 59703.366395187055, 0.049754650084258438},  // Delta* 0.65149, x 35.739, Re 100
    {0.87, 0.010141987829614604, 0.00017, 0, 0.045, 8548.7136510289511, 0.69638821489505942},  // Delta* 0.65149, x 35.739, Re 0.1
    {0.87, 10.141987829614603, 0.00017, 0, 0.045, 28720.566318495501, 0.69638821489505942},  // Delta* 0.65149, x 35.739, Re 100
    {0.70, 0.012605042016806723, 0.00017, 0, 0.045, 6082.8299583919716, 0.88951915718420804},  // Delta* 0.65149, x 35.739, Re 0.1
    {0.70, 12.605042016806722, 0.00017, 0, 0.045, 17070.205940330754, 0.88951915718420804},  // Delta* 0.65149, x 35.739, Re 100
    {0.55, 0.0160427807486631, 0.00017, 0, 0.045, 15058.803934804821, 0.84226726030852272},  // Delta* 0.65149, x 35.739, Re 0.1
    {0.55, 16.042780748663098, 0.00017, 0, 0.045, 37989.608024207912, 0.84226726030852272},  // Delta* 0.65149, x 35.739, Re 100
    {0.38, 0.023219814241486069, 0.00017, 0, 0.045, 184259.53654550348, 0},  // Delta* 0.65149, x 35.739, Re 0.1, h < 0: clamped
    {0.38, 23.219814241486066, 0.00017, 0, 0.045, 435596.04518117243, 0},  // Delta* 0.65149, x 35.739, Re 100, h < 0: clamped
    {0.99, 0.0089126559714795012, 0.00017, 0, 0.075, 12922.256212836968, 0.058554883308608204},  // Delta* 1.0858, x 59.565, Re 0.1
    {0.99, 8.9126559714795004, 0.00017, 0, 0.075, 59150.45282544104, 0.058554883308608204},  // Delta* 1.0858, x 59.565, Re 100
    {0.87, 0.010141987829614604, 0.00017, 0, 0.075, 7638.038135226373, 0.72873130536351882},  // Delta* 1.0858, x 59.565, Re 0.1
    {0.87, 10.141987829614603, 0.00017, 0, 0.075, 25661.028051812547, 0.72873130536351882},  // Delta* 1.0858, x 59.565, Re 100
    {0.70, 0.012605042016806723, 0.00017, 0, 0.075, 4874.3254351099267, 0.91146890741431197},  // Delta* 1.0858, x 59.565, Re 0.1
    {0.70, 12.605042016806722, 0.00017, 0, 0.075, 13678.787598316268, 0.91146890741431197},  // Delta* 1.0858, x 59.565, Re 100
    {0.55, 0.0160427807486631, 0.00017, 0, 0.075, 13494.834964311287, 0.85864898036918713},  // Delta* 1.0858, x 59.565, Re 0.1
    {0.55, 16.042780748663098, 0.00017, 0, 0.075, 34044.104224018927, 0.85864898036918713},  // Delta* 1.0858, x 59.565, Re 100
    {0.38, 0.023219814241486069, 0.00017, 0, 0.075, 184259.53654550348, 0},  // Delta* 1.0858, x 59.565, Re 0.1, h < 0: clamped
    {0.38, 23.219814241486066, 0.00017, 0, 0.075, 435596.04518117243, 0},  // Delta* 1.0858, x 59.565, Re 100, h < 0: clamped
    {0.70, 1.1160714285714286, 6e-05, 9.6e-05, 0.045, 26674.155711614272, 0.9366415381456703},  // Delta* 18.282, x 217.46, Re 5
    {0.55, 5.6818181818181817, 0.00017, 9.6e-05, 0.075, 23733.757646833386, 0.85864898036918713},  // Delta* 1.0858, x 59.565, Re 20
  };
  for (const Row& r : rows) {
    const RadlSundaresanDrag l = law(r.filterSize);
    const DragInput in = input(r.alphaG, r.slip, r.dp, r.dMean);
    bool clamped = false;
    EXPECT_NEAR(l.correction(in, clamped), r.h, 1e-12) << r.alphaG << " " << r.dp << " " << r.filterSize;
    EXPECT_EQ(clamped, r.alphaG < 0.4) << r.alphaG;  // phi = 0.62: h < 0
    EXPECT_NEAR(l.coefficient(in), r.k, 1e-12 * r.k) << r.alphaG << " " << r.dp << " " << r.filterSize;
    // the same through the registry
    EXPECT_NEAR(exchangeCoefficientPerSolidVolume(makeDragLaw("RadlSundaresanFilteredBVK", test::fccContext(r.filterSize)), in),
                r.k, 1e-12 * r.k);
  }
}

TEST(RadlSundaresanDrag, VanishesAsTheFilterShrinks) {
  const DragInput in = input(0.7, 0.3, 8e-5);
  const double bvk = BeetstraDrag().coefficient(in);
  double previous = 1.0;
  for (double filter = 1e-2; filter >= 1e-12; filter /= 10.0) {
    bool clamped = true;
    const double correction = law(filter).correction(in, clamped);
    EXPECT_FALSE(clamped);
    EXPECT_GT(correction, 0.0);
    EXPECT_LT(correction, previous);
    previous = correction;
    // small x: H = h x / (a + x) -> h x / a, linear in the filter size
    const double x = law(filter).scaledFilterSize(in);
    EXPECT_NEAR(x / filter, law(1.0).scaledFilterSize(in), 1e-12 * x / filter);
  }
  EXPECT_LT(previous, 1e-8);  // H at a 1e-12 m filter
  EXPECT_NEAR(law(1e-12).coefficient(in), bvk, 1e-8 * bvk);
}

TEST(RadlSundaresanDrag, LargeFilterGivesTheFittedCorrection) {
  for (double phi : {0.005, 0.05, 0.2, 0.35, 0.5, 0.58}) {
    bool clamped = true;
    const double correction = law(1e6).correction(input(1.0 - phi, 0.1, 1e-4), clamped);
    EXPECT_NEAR(correction, RadlSundaresanDrag::largeFilterCorrection(phi), 1e-4) << phi;
    EXPECT_FALSE(clamped);
  }
}

TEST(RadlSundaresanDrag, DiluteLimitIsSingleParticleStokesDrag) {
  // a_g = 1: h(0) = 0, so no correction, and BVK gives Stokes drag V_p K = 3 pi mu d at Re -> 0.
  const double d = 1e-4;
  bool clamped = true;
  EXPECT_EQ(law(0.075).correction(input(1.0, 0.0, d), clamped), 0.0);
  EXPECT_FALSE(clamped);
  EXPECT_NEAR(particleVolume(d) * law(0.075).coefficient(input(1.0, 0.0, d)), 3.0 * kPi * kMuG * d,
              1e-12 * 3.0 * kPi * kMuG * d);
}

TEST(RadlSundaresanDrag, BoundedAndPositiveForEveryState) {
  // 1 - H in [0.053, 1] for all phi in [0, 0.99], filter sizes from 1 um to 1 km, particles of 10 um - 3 mm.
  for (int percent = 0; percent <= 99; ++percent)
    for (double filter : {1e-6, 1e-3, 0.045, 0.075, 1.0, 1e3})
      for (double dp : {1e-5, 6e-5, 3e-4, 3e-3}) {
        const DragInput in = input(1.0 - percent / 100.0, 0.5, dp);
        bool clamped = false;
        const double correction = law(filter).correction(in, clamped);
        EXPECT_GE(correction, 0.0);
        EXPECT_LE(correction, 0.947);
        if (percent != 60) {  // h(0.600) = 0 within round-off
          EXPECT_EQ(clamped, percent > 60) << percent;
        }
        EXPECT_GT(law(filter).coefficient(in), 0.0);
      }
}

TEST(RadlSundaresanDrag, DenseClampIsCountedInTheBatch) {
  const std::vector<double> alphaG{0.9, 0.5, 0.38, 0.36, 0.2}, slip(5, 0.2), dp(5, 7e-5), np(5, 1e6);
  ParcelDragBatch b;
  b.size = alphaG.size();
  b.alphaG = alphaG.data();
  b.slip = slip.data();
  b.dp = dp.data();
  b.np = np.data();
  b.rhoG = kRhoG;
  b.muG = kMuG;
  const DragLaw filtered = makeDragLaw("RadlSundaresanFilteredBVK", test::fccContext(0.075));
  std::vector<double> kappa(b.size);
  const DragStats st = computeParcelKappa(filtered, b, DragLimits{0.35}, kappa.data());
  // phi = 0.62, 0.64 and 0.65 (a_g = 0.2 is evaluated at the floor 0.35) are beyond the fit's h >= 0
  EXPECT_EQ(st.filterCorrectionClamped, 3u);
  EXPECT_EQ(st.alphaGFloored, 1u);
  std::vector<double> bvkKappa(b.size);
  computeParcelKappa(makeDragLaw("BeetstraVanDerHoefKuipers"), b, DragLimits{0.35}, bvkKappa.data());
  for (std::size_t p = 2; p < b.size; ++p) EXPECT_EQ(kappa[p], bvkKappa[p]) << p;  // clamped: H = 0
  for (std::size_t p = 0; p < 2; ++p) EXPECT_LT(kappa[p], bvkKappa[p]) << p;
}

TEST(RadlSundaresanDrag, NeedsItsContext) {
  EXPECT_THROW(makeDragLaw("RadlSundaresanFilteredBVK"), parcelflow::cfd::InternalError);
  DragLawContext c = test::fccContext(0.075);
  c.particleDensity = 0.0;
  EXPECT_THROW(RadlSundaresanDrag{c}, parcelflow::cfd::InternalError);
  c = test::fccContext(0.075);
  c.gravity = 0.0;
  EXPECT_THROW(RadlSundaresanDrag{c}, parcelflow::cfd::InternalError);
  EXPECT_THROW(RadlSundaresanDrag{test::fccContext(0.0)}, parcelflow::cfd::InternalError);
}
